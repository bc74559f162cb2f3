// OccupancyGrid(WorldAligned) vs pcl::VoxelGrid, same leaf, same cloud, same process.
#include <pcl/filters/voxel_grid.h>

#include "bench_common.h"
#include "metricmap/grid/occupancy_grid.h"

namespace metricmap::bench {
namespace {

constexpr float kLeaf = 0.1f;

// One filter object per run, reused for every iteration, as in a per-frame pipeline:
// metricmap keeps its scratch buffers between calls; pcl::VoxelGrid allocates inside filter().
void BM_OccupancyGrid(benchmark::State& state) {
  const auto cloud = kittiCloud();
  pcl::PointCloud<pcl::PointXYZ> out;
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setOrigin(GridOrigin::WorldAligned);
  grid.setCellSize(kLeaf);
  grid.setInputCloud(cloud);
  grid.setNumberOfThreads(static_cast<unsigned>(state.range(0)));
  resetPeakRss();
  const double base = peakRssMiB();
  for (auto _ : state) {
    grid.filter(out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["cells"] = static_cast<double>(out.size());
  report(state, cloud->size(), base);
}

// A fresh object every iteration: every buffer is new memory (first-call cost).
void BM_OccupancyGridFresh(benchmark::State& state) {
  const auto cloud = kittiCloud();
  pcl::PointCloud<pcl::PointXYZ> out;
  resetPeakRss();
  const double base = peakRssMiB();
  for (auto _ : state) {
    OccupancyGrid<pcl::PointXYZ> grid;
    grid.setOrigin(GridOrigin::WorldAligned);
    grid.setCellSize(kLeaf);
    grid.setInputCloud(cloud);
    grid.setNumberOfThreads(static_cast<unsigned>(state.range(0)));
    grid.filter(out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["cells"] = static_cast<double>(out.size());
  report(state, cloud->size(), base);
}

void BM_PclVoxelGrid(benchmark::State& state) {
  const auto cloud = kittiCloud();
  pcl::PointCloud<pcl::PointXYZ> out;
  pcl::VoxelGrid<pcl::PointXYZ> voxel;
  voxel.setLeafSize(kLeaf, kLeaf, kLeaf);
  voxel.setInputCloud(cloud);
  resetPeakRss();
  const double base = peakRssMiB();
  for (auto _ : state) {
    voxel.filter(out);
    benchmark::DoNotOptimize(out.data());
  }
  if (out.size() == cloud->size()) state.SkipWithError("VoxelGrid returned its input (overflow)");
  state.counters["cells"] = static_cast<double>(out.size());
  report(state, cloud->size(), base);
}

BENCHMARK(BM_OccupancyGrid)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK(BM_OccupancyGridFresh)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK(BM_PclVoxelGrid)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
}  // namespace metricmap::bench
