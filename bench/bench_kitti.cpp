// Per-scan cost of the KITTI pipeline without I/O: transform + accumulate (a global cloud) +
// 2D map counting, on the real 124k-point scan 000000, single-threaded.
#include <pcl/common/transforms.h>

#include "bench_common.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/kitti/kitti_sequence.h"
#include "metricmap/kitti/occupancy_map_2d.h"

namespace metricmap::bench {
namespace {

void BM_KittiScanTransformAccumulateMap(benchmark::State& state) {
  const KittiSequence seq{std::string(METRICMAP_DATA_DIR) + "/kitti_odometry_00", "00"};
  pcl::PointCloud<pcl::PointXYZ> scan;
  loadCloud(seq.scan(0), scan);
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const auto poses = readKittiPoses(seq.poses(), 6);
  const Eigen::Matrix4f to_world =
      kittiScanToWorld(poses[5], tr, KittiWorld::Camera).matrix().cast<float>();
  OccupancyMap2D map(0.1, MapPlane::XZ);
  pcl::PointCloud<pcl::PointXYZ> world, global;
  global.reserve(scan.size() * 64);
  for (auto _ : state) {
    pcl::transformPointCloud(scan, world, to_world);
    if (global.size() > scan.size() * 60) global.clear();  // bounded, like one sequence chunk
    global += world;
    map.add(world);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * scan.size()));
  state.counters["points"] = static_cast<double>(scan.size());
}

BENCHMARK(BM_KittiScanTransformAccumulateMap)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
}  // namespace metricmap::bench
