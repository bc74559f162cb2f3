#include "bench_common.h"

#include <sstream>

#include <benchmark/benchmark.h>

#include <fstream>

#include "metricmap/io/cloud_reader.h"
#include "metricmap/occupancy/ray_kernel.h"

#ifndef METRICMAP_DATA_DIR
#error "METRICMAP_DATA_DIR must be defined"
#endif

namespace metricmap::bench {

namespace {

// "model name (family F model M stepping S)" of the first CPU: virtual machines often name only
// the vendor's line, the numbers tell the generation.
std::string cpuModel() {
  std::ifstream info("/proc/cpuinfo");
  std::string name = "unknown", numbers;
  for (std::string line; std::getline(info, line) && !line.empty();) {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos || colon + 2 > line.size()) continue;
    const std::string key = line.substr(0, line.find_first_of("\t:"));
    const std::string value = line.substr(colon + 2);
    if (key == "model name") name = value;
    if (key == "cpu family") numbers += "family " + value;
    if (key == "model") numbers += " model " + value;
    if (key == "stepping") numbers += " stepping " + value;
  }
  return numbers.empty() ? name : name + " (" + numbers + ")";
}

// The CPU model and the ray walk it gets, in the header of every run's output.
const bool kContext = [] {
  benchmark::AddCustomContext("cpu_model", cpuModel());
  benchmark::AddCustomContext("ray_walk", detail::simdWalkName());
  return true;
}();

}  // namespace

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
