// Probabilistic occupancy, head to head: LogOddsMap::insertScan against liboctomap's
// OcTree::insertPointCloud (lazy evaluation off, no discretisation) on the same real KITTI
// scans in the world frame, same origin, resolution and 50 m max range, single thread.
#include <vector>

#include <octomap/OcTree.h>
#include <pcl/common/transforms.h>

#include "bench_common.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/ray_kernel.h"

namespace metricmap::bench {
namespace {

constexpr double kMaxRange = 50.0;
constexpr std::int64_t kOcto = 32768;

struct Scan {
  pcl::PointCloud<pcl::PointXYZ> points;
  Eigen::Vector3f origin;
  octomap::Pointcloud octo;
};

const std::vector<Scan>& scans() {
  static std::vector<Scan> all;
  if (!all.empty()) return all;
  const KittiSequence seq{std::string(METRICMAP_DATA_DIR) + "/kitti_odometry_00", "00"};
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const auto poses = readKittiPoses(seq.poses(), 6);
  for (std::size_t f = 0; f < 6; ++f) {
    pcl::PointCloud<pcl::PointXYZ> scan;
    loadCloud(seq.scan(f), scan);
    const Eigen::Isometry3d to_world = kittiScanToWorld(poses[f], tr, KittiWorld::Velodyne);
    Scan s;
    pcl::transformPointCloud(scan, s.points, to_world.matrix().cast<float>());
    s.origin = to_world.translation().cast<float>();
    for (const auto& p : s.points) s.octo.push_back(p.x, p.y, p.z);
    all.push_back(std::move(s));
  }
  return all;
}

double resolutionOf(const benchmark::State& state) {
  return static_cast<double>(state.range(0)) / 1000.0;
}

LogOddsParams paramsOf(const benchmark::State& state) {
  LogOddsParams p;
  p.resolution = resolutionOf(state);
  p.max_range = kMaxRange;
  return p;
}

void ourCounters(benchmark::State& state, const LogOddsMap& map, std::size_t points) {
  const LogOddsMemory m = map.memory();
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points));
  state.counters["points"] = static_cast<double>(points);
  state.counters["known_voxels"] = static_cast<double>(m.known_voxels);
  state.counters["bytes_per_voxel"] = m.bytes_per_known_voxel;
}

std::size_t octoKnownVoxels(const octomap::OcTree& tree) {
  std::size_t n = 0;
  const unsigned depth = tree.getTreeDepth();
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it)
    n += std::size_t{1} << (3 * (depth - it.getDepth()));
  return n;
}

void octoCounters(benchmark::State& state, const octomap::OcTree& tree, std::size_t points) {
  const std::size_t known = octoKnownVoxels(tree);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points));
  state.counters["points"] = static_cast<double>(points);
  state.counters["known_voxels"] = static_cast<double>(known);
  state.counters["bytes_per_voxel"] =
      static_cast<double>(tree.memoryUsage()) / static_cast<double>(known);
}

// One scan (frame 0, 124k points) into an empty map per iteration.
void BM_LogOddsMapFreshScan(benchmark::State& state) {
  const Scan& s = scans()[0];
  LogOddsMap map(paramsOf(state));
  for (auto _ : state) {
    map.clear();
    map.insertScan(s.points, s.origin);
  }
  ourCounters(state, map, s.points.size());
}

// The same with the portable (plain C++) ray walk forced: the walk of non-x86 CPUs, against the
// SIMD walk of BM_LogOddsMapFreshScan in the same run (within 3x).
void BM_LogOddsMapFreshScanPortable(benchmark::State& state) {
  const detail::ScopedRayPath portable(detail::RayPath::Portable);
  BM_LogOddsMapFreshScan(state);
}

// The same scan cast on range(1) threads (setThreads; the same map for every count), wall time.
void BM_LogOddsMapFreshScanThreads(benchmark::State& state) {
  const Scan& s = scans()[0];
  LogOddsMap map(paramsOf(state));
  map.setThreads(static_cast<unsigned>(state.range(1)));
  for (auto _ : state) {
    map.clear();
    map.insertScan(s.points, s.origin);
  }
  ourCounters(state, map, s.points.size());
}

// A new map per scan (what a user calling it once gets: fresh memory every time), threads.
void BM_LogOddsMapNewObjectThreads(benchmark::State& state) {
  const Scan& s = scans()[0];
  std::size_t known = 0;
  for (auto _ : state) {
    LogOddsMap map(paramsOf(state));
    map.setThreads(static_cast<unsigned>(state.range(1)));
    map.insertScan(s.points, s.origin);
    known = map.knownVoxels();
  }
  state.counters["known_voxels"] = static_cast<double>(known);
}

void BM_OctomapFreshScan(benchmark::State& state) {
  const Scan& s = scans()[0];
  const octomap::point3d origin(s.origin.x(), s.origin.y(), s.origin.z());
  std::unique_ptr<octomap::OcTree> tree;
  for (auto _ : state) {
    tree = std::make_unique<octomap::OcTree>(resolutionOf(state));
    tree->insertPointCloud(s.octo, origin, kMaxRange, false, false);
  }
  octoCounters(state, *tree, s.points.size());
}

// Frames 0-5 in turn into one map that keeps growing (the map of a drive).
void BM_LogOddsMapAccumulated(benchmark::State& state) {
  LogOddsMap map(paramsOf(state));
  std::size_t i = 0, points = 0;
  for (auto _ : state) {
    const Scan& s = scans()[i++ % 6];
    map.insertScan(s.points, s.origin);
    points += s.points.size();
  }
  ourCounters(state, map, points / std::max<std::size_t>(1, state.iterations()));
}

void BM_LogOddsMapAccumulatedThreads(benchmark::State& state) {
  LogOddsMap map(paramsOf(state));
  map.setThreads(static_cast<unsigned>(state.range(1)));
  std::size_t i = 0, points = 0;
  for (auto _ : state) {
    const Scan& s = scans()[i++ % 6];
    map.insertScan(s.points, s.origin);
    points += s.points.size();
  }
  ourCounters(state, map, points / std::max<std::size_t>(1, state.iterations()));
}

void BM_OctomapAccumulated(benchmark::State& state) {
  octomap::OcTree tree(resolutionOf(state));
  std::size_t i = 0, points = 0;
  for (auto _ : state) {
    const Scan& s = scans()[i++ % 6];
    tree.insertPointCloud(s.octo, octomap::point3d(s.origin.x(), s.origin.y(), s.origin.z()),
                          kMaxRange, false, false);
    points += s.points.size();
  }
  octoCounters(state, tree, points / std::max<std::size_t>(1, state.iterations()));
}

BENCHMARK(BM_LogOddsMapFreshScan)->Arg(200)->Arg(100)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_LogOddsMapFreshScanPortable)
    ->Arg(200)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);
BENCHMARK(BM_LogOddsMapFreshScanThreads)
    ->Args({200, 1})
    ->Args({200, 2})
    ->Args({100, 1})
    ->Args({100, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_LogOddsMapNewObjectThreads)
    ->Args({200, 1})
    ->Args({200, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_OctomapFreshScan)->Arg(200)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_LogOddsMapAccumulated)
    ->Arg(200)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(24);
BENCHMARK(BM_LogOddsMapAccumulatedThreads)
    ->Args({200, 1})
    ->Args({200, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(24);
BENCHMARK(BM_OctomapAccumulated)->Arg(200)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(6);

}  // namespace
}  // namespace metricmap::bench
