// LidarOdometry per scan (range crop, both downsamplings, ICP, map update) against PCL's GICP as
// `metricmap kitti --refine gicp` runs it, on the six bundled KITTI scans, one and two threads.
// The odometry runs the scans forward and back (0..5..0..) for 1000 scans and reports the median
// time per scan and the largest local map seen.
#include <algorithm>
#include <chrono>
#include <vector>

#include "bench_common.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/registration/scan_registration.h"
#include "metricmap/sequence/odometry_run.h"

namespace metricmap::bench {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

const std::vector<Cloud>& scans() {
  static const std::vector<Cloud> s = [] {
    const KittiSequence seq{std::string(METRICMAP_DATA_DIR) + "/kitti_odometry_00", "00"};
    std::vector<Cloud> out(6);
    for (std::size_t f = 0; f < 6; ++f) loadCloud(seq.scan(f), out[f]);
    return out;
  }();
  return s;
}

// 0 1 2 3 4 5 4 3 2 1 0 1 ...
std::size_t pingPong(std::size_t k) {
  const std::size_t m = k % 10;
  return m <= 5 ? m : 10 - m;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

void BM_LidarOdometryForwardAndBack(benchmark::State& state) {
  const auto& s = scans();
  std::vector<double> ms;
  std::size_t max_voxels = 0, max_points = 0, max_bytes = 0, restarts = 0;
  for (auto _ : state) {
    LidarOdometryConfig config;
    config.threads = static_cast<unsigned>(state.range(0));
    LidarOdometry odo(config);
    ms.clear();
    for (std::size_t k = 0; k < 1000; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const OdometryResult r = odo.registerFrame(s[pingPong(k)]);
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      restarts += r.restarted ? 1 : 0;
      max_voxels = std::max(max_voxels, odo.localMap().voxels());
      max_points = std::max(max_points, odo.localMap().points());
      max_bytes = std::max(max_bytes, odo.localMap().bytes());
    }
    benchmark::DoNotOptimize(odo.poses().back());
  }
  state.counters["median_ms_per_scan"] = median(ms);
  std::sort(ms.begin(), ms.end());
  state.counters["p90_ms"] = ms[ms.size() * 9 / 10];
  state.counters["max_ms"] = ms.back();
  state.counters["map_voxels_max"] = static_cast<double>(max_voxels);
  state.counters["map_points_max"] = static_cast<double>(max_points);
  state.counters["map_MiB_max"] = static_cast<double>(max_bytes) / (1024.0 * 1024.0);
  state.counters["restarts"] = static_cast<double>(restarts);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 1000));
}
BENCHMARK(BM_LidarOdometryForwardAndBack)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// One scan of the odometry in its steady state (frames 0-5 forward, the next scan timed), with
// 1 and 2 threads for the pairing (the poses are the same).
void BM_LidarOdometryScan(benchmark::State& state) {
  const auto& s = scans();
  std::size_t k = 0;
  LidarOdometryConfig config;
  config.threads = static_cast<unsigned>(state.range(0));
  LidarOdometry odo(config);
  for (auto _ : state) {
    state.PauseTiming();
    if (k % 10 == 0) odo.reset();  // keep the run forward-and-back, like the long run
    state.ResumeTiming();
    benchmark::DoNotOptimize(odo.registerFrame(s[pingPong(k)]));
    ++k;
  }
}
BENCHMARK(BM_LidarOdometryScan)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(3.0);

// PCL's GICP as `--refine gicp` uses it: registrationCloud (3-40 m, above the ground, 0.2 m
// voxels) of the new scan, then refineScanPose (two stages, 1.0 m then 0.25 m) against the
// previous scan's registration cloud, from the identity.
void BM_PclGicpScan(benchmark::State& state) {
  const auto& s = scans();
  std::vector<Cloud::Ptr> targets;
  for (const auto& c : s) targets.push_back(registrationCloud(c));
  RefineParams params;
  params.method = RefineMethod::Gicp;
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t f = 1 + k % 5;
    const auto source = registrationCloud(s[f]);
    benchmark::DoNotOptimize(
        refineScanPose(source, targets[f - 1], Eigen::Isometry3d::Identity(), params));
    ++k;
  }
}
BENCHMARK(BM_PclGicpScan)->Unit(benchmark::kMillisecond)->MinTime(3.0);

// The hand-carried scanner of balm_realworld_dev at the defaults a folder source gets (range
// window and voxel from the first scan, coarse then fine stage): the 40 scans read once, then
// registered in order by a new LidarOdometry per pass; the median registration time per scan.
void BM_OdometryHandCarriedDefaults(benchmark::State& state) {
  static const std::vector<Cloud> scans = [] {
    auto source = openScanSource(std::string(METRICMAP_SHARED_DATA_DIR) + "/balm_realworld_dev");
    std::vector<Cloud> out;
    for (std::size_t i = 0; i < source->size(); ++i) out.push_back(source->scan(i).points);
    return out;
  }();
  LidarOdometryConfig config;
  config.threads = static_cast<unsigned>(state.range(0));
  config = applyProfile(config, profileScan(toPoints3d(scans[0])), SensorProfileRequest{});
  std::vector<double> ms;
  for (auto _ : state) {
    LidarOdometry odo(config);
    for (const Cloud& c : scans) {
      const auto t0 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(odo.registerFrame(c));
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  state.counters["median_ms_per_scan"] = median(ms);
  state.counters["voxel_m"] = config.voxel_size;
  state.counters["coarse_voxel_m"] = config.coarse_voxel_size;
  state.SetItemsProcessed(static_cast<std::int64_t>(ms.size()));
}
BENCHMARK(BM_OdometryHandCarriedDefaults)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->Iterations(3);

}  // namespace
}  // namespace metricmap::bench
