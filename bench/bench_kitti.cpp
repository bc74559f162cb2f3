// Per-scan cost of the KITTI mapping pipeline without I/O: ScanMapper::addScan (range band,
// transform, accumulation into the global cloud, 2D map counting) on the real 124k-point scan
// 000000, single-threaded. A mapper holds at most 60 scans (one sequence chunk), then a new one
// is made outside the timed region.
#include <memory>

#include "bench_common.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/sequence/scan_mapper.h"

namespace metricmap::bench {
namespace {

void BM_ScanMapperAddScan(benchmark::State& state) {
  const KittiSequence seq{std::string(METRICMAP_DATA_DIR) + "/kitti_odometry_00", "00"};
  pcl::PointCloud<pcl::PointXYZ> scan;
  loadCloud(seq.scan(0), scan);
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const auto poses = readKittiPoses(seq.poses(), 6);
  const Eigen::Isometry3d pose = kittiScanToWorld(poses[5], tr, KittiWorld::Camera);
  ScanMapperConfig config;
  config.min_range = 2.5;
  config.voxel = static_cast<double>(state.range(0)) / 100.0;  // 0: no per-scan voxel
  auto mapper = std::make_unique<ScanMapper>(config);
  std::size_t scans = 0;
  for (auto _ : state) {
    if (++scans % 60 == 0) {
      state.PauseTiming();
      mapper = std::make_unique<ScanMapper>(config);
      state.ResumeTiming();
    }
    benchmark::DoNotOptimize(mapper->addScan(scan, pose));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * scan.size()));
  state.counters["points"] = static_cast<double>(scan.size());
}

BENCHMARK(BM_ScanMapperAddScan)
    ->ArgName("voxel_cm")
    ->Arg(0)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace
}  // namespace metricmap::bench
