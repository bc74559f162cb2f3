// LogOddsMap against hand-computed beams and, on real KITTI scans, a plain reference written
// here (every plane crossing of a beam, sorted; the voxel between two crossings): endpoints
// occupied, sensor voxel free, free voxels, merge of half-maps equal to the map of all scans.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include <octomap/OcTree.h>

#include <gtest/gtest.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "occupancy_scans.h"

namespace metricmap {
namespace {

using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>;

Key plainKey(const Eigen::Vector3d& p, double res) {
  return {static_cast<std::int64_t>(std::floor(p.x() / res)),
          static_cast<std::int64_t>(std::floor(p.y() / res)),
          static_cast<std::int64_t>(std::floor(p.z() / res))};
}

// The voxels a segment o -> e passes through, from o's up to, not including, e's: cut at every
// plane x|y|z = k * res, sort the parameters, take the voxel at each midpoint.
void plainWalk(const Eigen::Vector3d& o, const Eigen::Vector3d& e, double res,
               std::set<Key>& free) {
  std::vector<double> ts{0.0, 1.0};
  for (int a = 0; a < 3; ++a) {
    const double lo = std::min(o[a], e[a]), hi = std::max(o[a], e[a]);
    if (hi == lo) continue;
    for (double k = std::ceil(lo / res); k * res <= hi; k += 1.0) {
      ts.push_back((k * res - o[a]) / (e[a] - o[a]));
    }
  }
  std::sort(ts.begin(), ts.end());
  const Key end = plainKey(e, res);
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    if (ts[i + 1] - ts[i] < 1e-12) continue;
    const Key k = plainKey(o + 0.5 * (ts[i] + ts[i + 1]) * (e - o), res);
    if (k != end) free.insert(k);
  }
}

VoxelKey toKey(const Key& k) { return {std::get<0>(k), std::get<1>(k), std::get<2>(k)}; }

TEST(LogOddsMap, ParametersAreChecked) {
  for (double r : {0.0, -0.1, std::nan(""), std::numeric_limits<double>::infinity()}) {
    LogOddsParams p;
    p.resolution = r;
    EXPECT_THROW(LogOddsMap{p}, std::invalid_argument) << r;
  }
  for (double m : {0.0, -1.0, std::nan("")}) {
    LogOddsParams p;
    p.max_range = m;
    EXPECT_THROW(LogOddsMap{p}, std::invalid_argument) << m;
  }
  // a hit must raise occupancy and a miss lower it: else no voxel is ever occupied (or free)
  for (double hit : {1.0, 0.5, 0.2, 0.0, std::nan("")}) {
    LogOddsParams p;
    p.prob_hit = hit;
    EXPECT_THROW(LogOddsMap{p}, std::invalid_argument) << hit;
  }
  for (double miss : {0.0, 0.5, 0.8, 1.0, std::nan("")}) {
    LogOddsParams p;
    p.prob_miss = miss;
    EXPECT_THROW(LogOddsMap{p}, std::invalid_argument) << miss;
  }
  LogOddsParams p;
  p = LogOddsParams();
  p.clamp_min = 0.9;
  p.clamp_max = 0.2;
  EXPECT_THROW(LogOddsMap{p}, std::invalid_argument);
  // OctoMap's defaults, as log-odds: liboctomap's own values, bit for bit
  LogOddsMap map;
  const octomap::OcTree tree(0.1);
  EXPECT_EQ(map.hitLogOdds(), tree.getProbHitLog());
  EXPECT_EQ(map.missLogOdds(), tree.getProbMissLog());
  EXPECT_EQ(map.clampMinLogOdds(), tree.getClampingThresMinLog());
  EXPECT_EQ(map.clampMaxLogOdds(), tree.getClampingThresMaxLog());
  EXPECT_EQ(map.thresholdLogOdds(), tree.getOccupancyThresLog());
}

TEST(LogOddsMap, HandBeams) {
  LogOddsParams p;
  p.resolution = 0.1;
  p.max_range = 2.0;
  LogOddsMap map(p);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back({1.05f, 0.05f, 0.05f});  // along x: voxels 0..9 free, 10 hit
  cloud.push_back({0.55f, 0.05f, 0.05f});  // ends in voxel 5, which the first beam crosses
  cloud.push_back({0.05f, 5.05f, 0.05f});  // 5 m along y: cut at 2 m, no hit
  cloud.push_back({std::nanf(""), 0.0f, 0.0f});
  cloud.push_back({0.0f, std::numeric_limits<float>::infinity(), 0.0f});
  const ScanInsertReport r = map.insertScan(cloud, Eigen::Vector3f(0.05f, 0.05f, 0.05f));
  EXPECT_EQ(r.points, 5u);
  EXPECT_EQ(r.non_finite, 2u);
  EXPECT_EQ(r.beams, 3u);
  EXPECT_EQ(r.beams_cut, 1u);
  EXPECT_EQ(r.hit_voxels, 2u);
  for (int x = 0; x < 10; ++x) {
    const VoxelState want = x == 5 ? VoxelState::Occupied : VoxelState::Free;
    EXPECT_EQ(map.state(VoxelKey{x, 0, 0}), want) << x;
  }
  EXPECT_EQ(map.state(VoxelKey{10, 0, 0}), VoxelState::Occupied);
  EXPECT_EQ(*map.logOdds({10, 0, 0}), map.hitLogOdds());
  EXPECT_EQ(*map.logOdds({3, 0, 0}), map.missLogOdds());  // once, though two beams cross it
  EXPECT_EQ(map.state(VoxelKey{11, 0, 0}), VoxelState::Unknown);
  // the cut beam: voxels 1..19 along y free (0 is the sensor's), 20 (the cut point's) untouched
  for (int y = 1; y < 20; ++y) EXPECT_EQ(map.state(VoxelKey{0, y, 0}), VoxelState::Free) << y;
  EXPECT_EQ(map.state(VoxelKey{0, 20, 0}), VoxelState::Unknown);
  EXPECT_EQ(map.state(VoxelKey{0, 50, 0}), VoxelState::Unknown);
  EXPECT_EQ(map.knownVoxels(), 11u + 19u);
  EXPECT_EQ(map.occupiedVoxels(), 2u);
  EXPECT_EQ(map.freeVoxels(), 28u);
  VoxelKey lo, hi;
  ASSERT_TRUE(map.keyBounds(lo, hi));
  EXPECT_EQ(lo, (VoxelKey{0, 0, 0}));
  EXPECT_EQ(hi, (VoxelKey{10, 19, 0}));
  EXPECT_NEAR(map.probability(Eigen::Vector3d(1.05, 0.05, 0.05)), 0.7, 1e-6);
  EXPECT_DOUBLE_EQ(map.probability(Eigen::Vector3d(9, 9, 9)), 0.5);
  // repeated hits clamp at 0.971
  for (int i = 0; i < 10; ++i) map.insertScan(cloud, Eigen::Vector3f(0.05f, 0.05f, 0.05f));
  EXPECT_EQ(*map.logOdds({10, 0, 0}), map.clampMaxLogOdds());
  EXPECT_EQ(*map.logOdds({3, 0, 0}), map.clampMinLogOdds());
}

TEST(LogOddsMap, BadScansLeaveTheMapUnchanged) {
  LogOddsMap map;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back({1.0f, 1.0f, 1.0f});
  map.insertScan(cloud, Eigen::Vector3f::Zero());
  const std::size_t known = map.knownVoxels();
  cloud.push_back({1e9f, 0.0f, 0.0f});  // 10^10 voxels away: beyond the key space
  EXPECT_THROW(map.insertScan(cloud, Eigen::Vector3f::Zero()), CapacityError);
  EXPECT_THROW(map.insertScan(cloud, Eigen::Vector3f(std::nanf(""), 0, 0)), std::invalid_argument);
  EXPECT_EQ(map.knownVoxels(), known);
  pcl::PointCloud<pcl::PointXYZ> empty;
  EXPECT_EQ(map.insertScan(empty, Eigen::Vector3f::Zero()).beams, 0u);
  EXPECT_EQ(map.knownVoxels(), known);
  // a 64-bit key space: 50 km from the world origin at 0.1 m is fine (OctoMap stops at 3.2 km)
  pcl::PointCloud<pcl::PointXYZ> far;
  far.push_back({50001.0f, 0.0f, 0.0f});
  map.insertScan(far, Eigen::Vector3f(50000.0f, 0.0f, 0.0f));
  EXPECT_EQ(map.state(Eigen::Vector3d(50001.0, 0.0, 0.0)), VoxelState::Occupied);
}

// Beams kilometres long and diagonal: the scan's box is too large for the dense per-scan bits,
// so the hashed per-scan blocks are used; the same voxels as the plain walk.
// The map checks the memory budget as a scan's blocks are collected: a resolution far too fine
// for the budget is refused naming the budget and the resolution, the map unchanged.
TEST(LogOddsMap, MemoryBudgetIsCheckedAsTheMapGrows) {
  const std::uint64_t saved = memoryBudget();
  LogOddsParams p;
  p.resolution = 0.002;
  p.max_range = 50.0;
  LogOddsMap map(p);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 36; ++i) {  // ~90 000 blocks of 8^3 voxels: ~300 MB
    const float a = static_cast<float>(i) * 0.174533f;
    cloud.push_back({40.0f * std::cos(a), 40.0f * std::sin(a), 1.0f});
  }
  setMemoryBudget(std::uint64_t{64} << 20);
  try {
    map.insertScan(cloud, Eigen::Vector3f::Zero());
    ADD_FAILURE() << "a 0.002 m map of 40 m beams fitted in 64 MiB";
  } catch (const CapacityError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("memory budget of 64 MiB (--max-memory"), std::string::npos) << m;
    EXPECT_NE(m.find("resolution 0.002 m"), std::string::npos) << m;
  }
  setMemoryBudget(saved);
  EXPECT_EQ(map.knownVoxels(), 0u);
  p.resolution = 0.2;  // the same scan at a sane resolution fits
  LogOddsMap coarse(p);
  setMemoryBudget(std::uint64_t{64} << 20);
  EXPECT_GT(coarse.insertScan(cloud, Eigen::Vector3f::Zero()).beams, 0u);
  setMemoryBudget(saved);
}

TEST(LogOddsMap, LongBeamsThroughTheSparsePath) {
  LogOddsParams p;
  p.resolution = 0.1;  // no max range
  LogOddsMap map(p);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back({3000.37f, 2000.11f, 1000.73f});
  cloud.push_back({-2500.2f, 1500.9f, -800.4f});
  const Eigen::Vector3f origin(0.33f, -0.21f, 1.7f);
  const ScanInsertReport r = map.insertScan(cloud, origin);
  EXPECT_EQ(r.beams_cut, 0u);
  std::set<Key> free;
  for (const auto& pt : cloud) {
    plainWalk(origin.cast<double>(), pt.getVector3fMap().cast<double>(), p.resolution, free);
  }
  ASSERT_GT(free.size(), 100000u);
  std::size_t ok = 0;
  for (const Key& k : free) ok += map.state(toKey(k)) == VoxelState::Free ? 1 : 0;
  EXPECT_GE(static_cast<double>(ok), 0.999 * static_cast<double>(free.size()));
  EXPECT_NEAR(static_cast<double>(map.knownVoxels()), static_cast<double>(free.size() + 2),
              0.001 * static_cast<double>(free.size()));
  for (const auto& pt : cloud)
    EXPECT_EQ(map.state(pt.getVector3fMap().cast<double>()), VoxelState::Occupied);
}

// Beams that start and end on voxel edges and corners (where rounding decides the walk, and
// OctoMap's walk can step past the end voxel before its length test stops it): every end voxel
// is occupied, every marked voxel lies within one voxel of the beam's voxels, and (under ASan)
// nothing is written outside the scan's box.
TEST(LogOddsMap, BeamsThroughVoxelCorners) {
  LogOddsParams p;
  p.resolution = 0.2;
  LogOddsMap map(p);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int x = -6; x <= 6; ++x)
    for (int y = -6; y <= 6; ++y)
      for (int z = -3; z <= 3; ++z)
        cloud.push_back(pcl::PointXYZ(0.2f * static_cast<float>(x), 0.2f * static_cast<float>(y),
                                      0.2f * static_cast<float>(z)));
  const Eigen::Vector3f origin(0.4f, -0.2f, 0.0f);
  const ScanInsertReport r = map.insertScan(cloud, origin);
  EXPECT_EQ(r.beams, cloud.size());
  for (const auto& pt : cloud)
    EXPECT_EQ(map.state(map.keyOf(pt.getVector3fMap().cast<double>())), VoxelState::Occupied);
  VoxelKey lo, hi;
  ASSERT_TRUE(map.keyBounds(lo, hi));
  EXPECT_GE(lo.x, -7);
  EXPECT_LE(hi.x, 7);
  EXPECT_GE(lo.y, -7);
  EXPECT_LE(hi.y, 7);
  EXPECT_GE(lo.z, -4);
  EXPECT_LE(hi.z, 4);
}

// One real scan, every 8th point (15.6k beams), 0.2 m, 50 m: against the plain reference.
TEST(LogOddsMap, KittiScanAgainstPlainWalk) {
  const test::WorldScan scan = test::subsample(test::kittiWorldScan(3), 8);
  LogOddsParams p;
  p.resolution = 0.2;
  p.max_range = 50.0;
  LogOddsMap map(p);
  map.insertScan(scan.points, scan.origin);
  const Eigen::Vector3d o = scan.origin.cast<double>();
  std::set<Key> hits, free;
  for (const auto& pt : scan.points) {
    const Eigen::Vector3d e = pt.getVector3fMap().cast<double>();
    const double r = (e - o).norm();
    if (r <= p.max_range) {
      hits.insert(plainKey(e, p.resolution));
      plainWalk(o, e, p.resolution, free);
    } else {
      plainWalk(o, o + (e - o) * (p.max_range / r), p.resolution, free);
    }
  }
  for (const Key& k : hits) free.erase(k);
  ASSERT_GT(hits.size(), 10000u);
  ASSERT_GT(free.size(), 100000u);
  // every endpoint voxel inside max range is occupied (a hit wins over any miss)
  std::size_t hit_ok = 0;
  for (const Key& k : hits) hit_ok += map.state(toKey(k)) == VoxelState::Occupied ? 1 : 0;
  EXPECT_GE(hit_ok, hits.size() - hits.size() / 10000);  // float vs double keys on faces
  // the sensor's voxel is free
  EXPECT_EQ(map.state(map.keyOf(o)), VoxelState::Free);
  EXPECT_EQ(hits.count(plainKey(o, p.resolution)), 0u);
  // free voxels agree but for beams through voxel edges and corners
  std::size_t free_ok = 0;
  for (const Key& k : free) free_ok += map.state(toKey(k)) == VoxelState::Free ? 1 : 0;
  std::printf("plain reference: %zu hit voxels (%zu occupied), %zu free (%zu free), map %zu\n",
              hits.size(), hit_ok, free.size(), free_ok, map.knownVoxels());
  EXPECT_GE(static_cast<double>(free_ok), 0.999 * static_cast<double>(free.size()));
  EXPECT_NEAR(static_cast<double>(map.knownVoxels()),
              static_cast<double>(hits.size() + free.size()),
              0.001 * static_cast<double>(map.knownVoxels()));
  // one update each: exactly the hit or the miss log-odds
  std::size_t single = 0;
  map.forEachKnown([&](const VoxelKey&, float l) {
    single += (l == map.hitLogOdds() || l == map.missLogOdds()) ? 1 : 0;
  });
  EXPECT_EQ(single, map.knownVoxels());
}

// Merge of the half-maps (frames 0, 2, 4 and 1, 3, 5) equals the map of all six frames where
// no clamping occurs: here the bounds are far apart, so it never does.
TEST(LogOddsMap, MergeOfHalvesEqualsTheWhole) {
  LogOddsParams p;
  p.resolution = 0.2;
  p.max_range = 30.0;
  p.clamp_min = 1e-6;
  p.clamp_max = 1.0 - 1e-6;
  LogOddsMap even(p), odd(p), all(p);
  for (std::size_t f = 0; f < 6; ++f) {
    const test::WorldScan s = test::subsample(test::kittiWorldScan(f), 4);
    (f % 2 == 0 ? even : odd).insertScan(s.points, s.origin);
    all.insertScan(s.points, s.origin);
  }
  even.merge(odd);
  ASSERT_EQ(even.knownVoxels(), all.knownVoxels());
  std::size_t equal = 0, several = 0;
  all.forEachKnown([&](const VoxelKey& k, float l) {
    const std::optional<float> m = even.logOdds(k);
    equal += (m && std::abs(*m - l) <= 1e-5f) ? 1 : 0;
    several += (l != all.hitLogOdds() && l != all.missLogOdds()) ? 1 : 0;
  });
  EXPECT_EQ(equal, all.knownVoxels());
  EXPECT_GT(several, 10000u);  // voxels seen by several scans: the sums are really tested
  EXPECT_EQ(even.occupiedVoxels(), all.occupiedVoxels());
  // different models do not merge
  LogOddsParams q = p;
  q.resolution = 0.1;
  LogOddsMap other(q);
  EXPECT_THROW(even.merge(other), std::invalid_argument);
}

// The cloud's own sensor pose (PCD VIEWPOINT) gives the map of the world points.
TEST(LogOddsMap, SensorPoseFromTheCloud) {
  const KittiSequence seq{dataPath("kitti_odometry_00"), "00"};
  pcl::PointCloud<pcl::PointXYZ> local;
  loadCloud(seq.scan(5), local);
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const Eigen::Isometry3f pose =
      kittiScanToWorld(readKittiPoses(seq.poses(), 6)[5], tr, KittiWorld::Velodyne).cast<float>();
  local.sensor_origin_ << pose.translation(), 0.0f;
  local.sensor_orientation_ = Eigen::Quaternionf(pose.rotation());
  const test::WorldScan world = test::subsample(test::kittiWorldScan(5), 1);
  LogOddsParams p;
  p.resolution = 0.2;
  p.max_range = 50.0;
  LogOddsMap a(p), b(p);
  a.insertScan(local);
  b.insertScan(world.points, world.origin);
  ASSERT_GT(b.knownVoxels(), 100000u);
  std::size_t same = 0;
  b.forEachKnown([&](const VoxelKey& k, float l) {
    const std::optional<float> m = a.logOdds(k);
    same += (m && *m == l) ? 1 : 0;
  });
  // the quaternion round trip and the transform's rounding move a few points across faces
  EXPECT_GE(static_cast<double>(same), 0.999 * static_cast<double>(b.knownVoxels()));
  EXPECT_NEAR(static_cast<double>(a.knownVoxels()), static_cast<double>(b.knownVoxels()),
              0.001 * static_cast<double>(b.knownVoxels()));
}

}  // namespace
}  // namespace metricmap
