#include "metricmap/mapping/map_sinks.h"

#include <cmath>
#include <memory>
#include <vector>

#include <pcl/common/transforms.h>

#include "metricmap/grid/occupancy_grid.h"

namespace metricmap {

pcl::PointCloud<pcl::PointXYZ> voxelAverage(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                            double voxel) {
  pcl::PointCloud<pcl::PointXYZ> out;
  if (cloud.empty()) return out;
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setOrigin(GridOrigin::WorldAligned);
  grid.setCellSize(static_cast<float>(voxel));
  grid.setInputCloud(std::make_shared<const pcl::PointCloud<pcl::PointXYZ>>(cloud));
  grid.filter(out);
  return out;
}

HitMapSink::HitMapSink(double resolution, MapPlane plane, const Eigen::Vector3f& up,
                       double min_height, double max_height)
    : map_(resolution, plane), up_(up), min_height_(min_height), max_height_(max_height) {}

std::uint64_t HitMapSink::insert(const SinkScan& scan) {
  if (min_height_ == -HUGE_VAL && max_height_ == HUGE_VAL) {
    map_.add(scan.averaged);  // no band: every point is mapped
    return scan.averaged.size();
  }
  pcl::PointCloud<pcl::PointXYZ> band;
  band.reserve(scan.averaged.size());
  for (const auto& p : scan.averaged) {
    const float h = up_.dot(p.getVector3fMap());
    if (h >= min_height_ && h <= max_height_) band.push_back(p);
  }
  map_.add(band);
  return band.size();
}

LogOddsGrid2DSink::LogOddsGrid2DSink(const LogOddsParams& params, MapPlane plane,
                                     const Eigen::Vector3f& up, double band_min, double band_max)
    : grid_(params),
      plane_(plane),
      up_(up.normalized()),
      band_min_(band_min),
      band_max_(band_max) {}

std::uint64_t LogOddsGrid2DSink::insert(const SinkScan& scan) {
  const int a = plane_ == MapPlane::YZ ? 1 : 0;
  const int b = plane_ == MapPlane::XY ? 1 : 2;
  const Eigen::Vector3f s = scan.pose.translation().cast<float>();
  const float base = up_.dot(s);
  std::vector<Eigen::Vector2f> ends;
  ends.reserve(scan.world.size());
  for (const auto& p : scan.world) {
    const Eigen::Vector3f v = p.getVector3fMap();
    const double h = static_cast<double>(up_.dot(v) - base);
    if (h >= band_min_ && h <= band_max_) ends.emplace_back(v[a], v[b]);
  }
  grid_.insertScan(Eigen::Vector2f(s[a], s[b]), ends);
  return ends.size();
}

LogOddsMapSink::LogOddsMapSink(const LogOddsParams& params) : map_(params) {}

std::uint64_t LogOddsMapSink::insert(const SinkScan& scan) {
  pcl::PointCloud<pcl::PointXYZ> full_world;
  pcl::transformPointCloud(scan.in_sensor, full_world, scan.pose.matrix().cast<float>());
  map_.insertScan(full_world, scan.pose.translation().cast<float>());
  return full_world.size();
}

GlobalCloudSink::GlobalCloudSink(double voxel) : voxel_(voxel) {}

std::uint64_t GlobalCloudSink::insert(const SinkScan& scan) {
  cloud_ += scan.averaged;
  return scan.averaged.size();
}

pcl::PointCloud<pcl::PointXYZ> GlobalCloudSink::cloud() const {
  return voxel_ > 0.0 ? voxelAverage(cloud_, voxel_) : cloud_;
}

}  // namespace metricmap
