// AdaptiveOctree vs pcl::octree::OctreePointCloudPointVector with dynamic depth, same cloud.
#include <pcl/octree/octree_pointcloud_pointvector.h>

#include "bench_common.h"
#include "metricmap/octree/adaptive_octree.h"

namespace metricmap::bench {
namespace {

constexpr std::size_t kMaxPoints = 20;
constexpr float kMinCell = 0.2f;

void BM_AdaptiveOctree(benchmark::State& state) {
  const auto cloud = kittiCloud();
  resetPeakRss();
  const double base = peakRssMiB();
  std::uint64_t leaves = 0;
  for (auto _ : state) {
    AdaptiveOctree<pcl::PointXYZ> octree;
    octree.setMaxPointsPerLeaf(kMaxPoints);
    octree.setMinCellSize(kMinCell);
    octree.setInputCloud(cloud);
    octree.compute();
    leaves = octree.getStatistics().occupied_leaves;
  }
  state.counters["occupied_leaves"] = static_cast<double>(leaves);
  report(state, cloud->size(), base);
}

void BM_PclOctreeDynamicDepth(benchmark::State& state) {
  const auto cloud = kittiCloud();
  resetPeakRss();
  const double base = peakRssMiB();
  std::uint64_t leaves = 0;
  for (auto _ : state) {
    pcl::octree::OctreePointCloudPointVector<pcl::PointXYZ> octree(kMinCell);
    octree.enableDynamicDepth(kMaxPoints);
    octree.setInputCloud(cloud);
    octree.addPointsFromInputCloud();
    leaves = octree.getLeafCount();
  }
  state.counters["occupied_leaves"] = static_cast<double>(leaves);
  report(state, cloud->size(), base);
}

BENCHMARK(BM_AdaptiveOctree)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_PclOctreeDynamicDepth)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
}  // namespace metricmap::bench
