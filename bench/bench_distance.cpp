// Distance fields, head to head: DistanceField against OctoMap's dynamicEDT3D
// (DynamicEDTOctomap + update()) on the log-odds map of KITTI frames 0-5 at 0.2 m, the same
// box (the map's known voxels' bounds) and clamp (5 m); and an incremental update after
// frame 5 against recomputing, both on one thread. CPU times are the process's (all threads).
#include <memory>
#include <string>

#include <benchmark/benchmark.h>
#include <dynamicEDT3D/dynamicEDTOctomap.h>
#include <octomap/OcTree.h>
#include <pcl/common/transforms.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/distance/distance_field.h"
#include "metricmap/distance/distance_sources.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {
namespace {

constexpr double kResolution = 0.2, kClamp = 5.0, kMaxRange = 50.0;

/// The log-odds map of frames [0, frames) of the bundled KITTI scans.
LogOddsMap kittiMap(std::size_t frames) {
  const KittiSequence seq{std::string(METRICMAP_DATA_DIR) + "/kitti_odometry_00", "00"};
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const auto poses = readKittiPoses(seq.poses(), frames);
  LogOddsParams p;
  p.resolution = kResolution;
  p.max_range = kMaxRange;
  LogOddsMap map(p);
  map.setThreads(0);
  for (std::size_t f = 0; f < frames; ++f) {
    pcl::PointCloud<pcl::PointXYZ> scan, world;
    loadCloud(seq.scan(f), scan);
    const Eigen::Isometry3d to_world = kittiScanToWorld(poses[f], tr, KittiWorld::Velodyne);
    pcl::transformPointCloud(scan, world, to_world.matrix().cast<float>());
    map.insertScan(world, to_world.translation().cast<float>());
  }
  return map;
}

const LogOddsMap& map6() {
  static const LogOddsMap map = kittiMap(6);
  return map;
}

DistanceFieldParams params(bool incremental, unsigned threads = 1) {
  DistanceFieldParams p;
  p.max_distance = kClamp;
  p.incremental = incremental;
  p.threads = threads;
  return p;
}

void boxCounters(benchmark::State& state, const DistanceField& f) {
  state.counters["nx"] = static_cast<double>(f.shape()[0]);
  state.counters["ny"] = static_cast<double>(f.shape()[1]);
  state.counters["nz"] = static_cast<double>(f.shape()[2]);
  state.counters["voxels_per_s"] =
      benchmark::Counter(static_cast<double>(f.voxels()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

// range(0): threads (1: the single-thread figure compared with dynamicEDT3D's single thread)
void BM_DistanceFieldKitti(benchmark::State& state) {
  const LogOddsMap& map = map6();
  const DistanceFieldParams p = params(false, static_cast<unsigned>(state.range(0)));
  std::unique_ptr<DistanceField> f;
  for (auto _ : state) {
    f = std::make_unique<DistanceField>(occupancyBoxOf(map, p), p);
    benchmark::DoNotOptimize(f->field().data());
  }
  boxCounters(state, *f);
}
BENCHMARK(BM_DistanceFieldKitti)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_DynamicEDTOctomapKitti(benchmark::State& state) {
  const LogOddsMap& map = map6();
  // the same voxels in an octomap::OcTree, the same box as DistanceField's
  octomap::OcTree tree(kResolution);
  map.forEachKnown([&](const VoxelKey& k, float lo) {
    const Eigen::Vector3d c = map.centerOf(k);
    tree.setNodeValue(octomap::point3d(static_cast<float>(c.x()), static_cast<float>(c.y()),
                                       static_cast<float>(c.z())),
                      lo, true);
  });
  VoxelKey lo, hi;
  map.keyBounds(lo, hi);
  const Eigen::Vector3d a = map.centerOf(lo), b = map.centerOf(hi);
  const octomap::point3d bmin(static_cast<float>(a.x()), static_cast<float>(a.y()),
                              static_cast<float>(a.z()));
  const octomap::point3d bmax(static_cast<float>(b.x()), static_cast<float>(b.y()),
                              static_cast<float>(b.z()));
  for (auto _ : state) {
    DynamicEDTOctomap edt(static_cast<float>(kClamp), &tree, bmin, bmax, false);
    edt.update();
    benchmark::DoNotOptimize(edt.getDistance(bmin));
  }
  state.counters["voxels_per_s"] = benchmark::Counter(
      static_cast<double>((hi.x - lo.x + 1) * (hi.y - lo.y + 1) * (hi.z - lo.z + 1)) *
          static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DynamicEDTOctomapKitti)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime()
    ->Iterations(2);

// Frame 5 inserted into the map of frames 0-4: update() of a field kept incremental, against
// recomputing the field of the new map over the same box.
struct UpdateCase {
  LogOddsMap before = kittiMap(5);
  LogOddsMap after = map6();
  KeyBox box;
  UpdateCase() {
    const OccupancyBox b = occupancyBoxOf(before, params(false));
    box = {b.min_key, b.shape};
  }
};
UpdateCase& updateCase() {
  static UpdateCase c;
  return c;
}

void BM_DistanceFieldUpdateOneScan(benchmark::State& state) {
  UpdateCase& c = updateCase();
  std::size_t lines = 0, changed = 0;
  for (auto _ : state) {
    state.PauseTiming();
    DistanceField f(occupancyBoxOf(c.before, params(true), c.box), params(true));
    state.ResumeTiming();
    const DistanceUpdateReport r = f.update(c.after);
    lines = r.lines;
    changed = r.changed_voxels;
  }
  state.counters["changed_voxels"] = static_cast<double>(changed);
  state.counters["lines"] = static_cast<double>(lines);
}
BENCHMARK(BM_DistanceFieldUpdateOneScan)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

void BM_DistanceFieldRecomputeOneScan(benchmark::State& state) {
  UpdateCase& c = updateCase();
  for (auto _ : state) {
    DistanceField f(occupancyBoxOf(c.after, params(false), c.box), params(false));
    benchmark::DoNotOptimize(f.field().data());
  }
}
BENCHMARK(BM_DistanceFieldRecomputeOneScan)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace
}  // namespace metricmap
