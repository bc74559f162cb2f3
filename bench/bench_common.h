#pragma once
// Shared set-up for the head-to-head benchmarks: the KITTI scans, replicated, and peak memory.
#include <fstream>
#include <string>

#include <benchmark/benchmark.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace metricmap::bench {

/// The six bundled KITTI scans (frames 0-5 of sequence 00), each copy shifted by 20 m in x,
/// until at least `min_points` points: ~3.6 M real LiDAR points by default.
pcl::PointCloud<pcl::PointXYZ>::ConstPtr kittiCloud(std::size_t min_points = 3000000);

/// Resident-set high-water mark of this process, in MiB (VmHWM).
double peakRssMiB();
/// Reset the high-water mark to the current RSS (Linux /proc/self/clear_refs).
void resetPeakRss();

/// Records points/s and the peak RSS reached while the benchmark ran.
inline void report(benchmark::State& state, std::size_t points, double base_mib) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points));
  state.counters["points"] = static_cast<double>(points);
  state.counters["peak_rss_MiB"] = peakRssMiB();
  state.counters["extra_rss_MiB"] = peakRssMiB() - base_mib;
}

}  // namespace metricmap::bench
