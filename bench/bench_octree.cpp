// AdaptiveOctree vs pcl::octree::OctreePointCloudPointVector with dynamic depth, same cloud.
#include <pcl/octree/octree_pointcloud_pointvector.h>

#include "bench_common.h"
#include "metricmap/octree/adaptive_octree.h"

namespace metricmap::bench {
namespace {

constexpr std::size_t kMaxPoints = 20;
constexpr float kMinCell = 0.2f;

// One octree object reused across iterations (per-frame use): its scratch buffers stay.
void BM_AdaptiveOctree(benchmark::State& state) {
  const auto cloud = kittiCloud();
  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(kMaxPoints);
  octree.setMinCellSize(kMinCell);
  octree.setInputCloud(cloud);
  octree.setNumberOfThreads(static_cast<unsigned>(state.range(0)));
  resetPeakRss();
  const double base = peakRssMiB();
  for (auto _ : state) octree.compute();
  state.counters["occupied_leaves"] = static_cast<double>(octree.getStatistics().occupied_leaves);
  state.counters["max_depth"] = octree.getStatistics().max_depth;
  state.counters["total_nodes"] = static_cast<double>(octree.getStatistics().total_nodes);
  report(state, cloud->size(), base);
}

// A fresh object every iteration: all memory is new (first-call cost).
void BM_AdaptiveOctreeFresh(benchmark::State& state) {
  const auto cloud = kittiCloud();
  resetPeakRss();
  const double base = peakRssMiB();
  std::uint64_t leaves = 0;
  for (auto _ : state) {
    AdaptiveOctree<pcl::PointXYZ> octree;
    octree.setMaxPointsPerLeaf(kMaxPoints);
    octree.setMinCellSize(kMinCell);
    octree.setInputCloud(cloud);
    octree.setNumberOfThreads(static_cast<unsigned>(state.range(0)));
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
  unsigned depth = 0;
  for (auto _ : state) {
    pcl::octree::OctreePointCloudPointVector<pcl::PointXYZ> octree(kMinCell);
    octree.enableDynamicDepth(kMaxPoints);
    octree.setInputCloud(cloud);
    octree.addPointsFromInputCloud();
    leaves = octree.getLeafCount();
    depth = octree.getTreeDepth();
  }
  state.counters["occupied_leaves"] = static_cast<double>(leaves);
  state.counters["max_depth"] = depth;
  report(state, cloud->size(), base);
}

BENCHMARK(BM_AdaptiveOctree)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK(BM_AdaptiveOctreeFresh)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK(BM_PclOctreeDynamicDepth)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
}  // namespace metricmap::bench
