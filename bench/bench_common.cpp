#include "bench_common.h"

#include <sstream>

#include "metricmap/io/cloud_reader.h"

#ifndef METRICMAP_DATA_DIR
#error "METRICMAP_DATA_DIR must be defined"
#endif

namespace metricmap::bench {

pcl::PointCloud<pcl::PointXYZ>::ConstPtr kittiCloud(std::size_t min_points) {
  static pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  if (cloud && cloud->size() >= min_points) return cloud;
  pcl::PointCloud<pcl::PointXYZ> frames;
  for (int f = 0; f < 6; ++f) {
    pcl::PointCloud<pcl::PointXYZ> scan;
    char name[64];
    std::snprintf(name, sizeof name, "/kitti_odometry_00/sequences/00/velodyne/%06d.bin", f);
    loadCloud(std::string(METRICMAP_DATA_DIR) + name, scan);
    frames += scan;
  }
  cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int copy = 0; cloud->size() < min_points; ++copy) {
    for (pcl::PointXYZ p : frames) {
      p.x += 20.0f * static_cast<float>(copy);
      cloud->push_back(p);
    }
  }
  return cloud;
}

double peakRssMiB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmHWM:", 0) == 0) {
      std::istringstream is(line.substr(6));
      double kib = 0;
      is >> kib;
      return kib / 1024.0;
    }
  }
  return 0.0;
}

void resetPeakRss() { std::ofstream("/proc/self/clear_refs") << "5"; }

}  // namespace metricmap::bench

namespace metricmap::bench {
namespace {

// Baseline for memory figures: the process with only the replicated cloud loaded.
void BM_DataOnly(benchmark::State& state) {
  const auto cloud = kittiCloud();
  for (auto _ : state) benchmark::DoNotOptimize(cloud->points.data());
  report(state, cloud->size(), peakRssMiB());
}
BENCHMARK(BM_DataOnly)->Iterations(1);

}  // namespace
}  // namespace metricmap::bench
