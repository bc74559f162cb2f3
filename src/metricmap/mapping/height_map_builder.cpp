#include "metricmap/mapping/height_map_builder.h"

#include <chrono>
#include <utility>

#include "metricmap/mapping/height_map.h"

namespace metricmap {

HeightMapBuilder::HeightMapBuilder(HeightMap& map, HeightMapPoses poses)
    : map_(map), poses_(std::move(poses)) {}

void HeightMapBuilder::addFrame(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud) {
  const std::size_t frame = frames_++;
  Eigen::Isometry3d pose = poses_.fixed;
  if (poses_.auto_floor) {
    const FloorPlane floor = fitFloor(camera_cloud, poses_.floor_distance);
    pose = cameraToMapFromFloor(floor.normal, floor.d);
    floors_.push_back({frame, floor});
  } else if (!poses_.trajectory.empty()) {
    pose = poses_.trajectory.at(frame);
  }
  const auto t0 = std::chrono::steady_clock::now();
  map_.addFrame(camera_cloud, pose);
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace metricmap
