// LogOddsMap against liboctomap's OcTree::insertPointCloud (lazy evaluation off, no
// discretisation) on real KITTI scans: same state and the same float log-odds per voxel.
#include <chrono>
#include <cstdio>

#include <octomap/OcTree.h>

#include <gtest/gtest.h>

#include "metricmap/occupancy/log_odds_map.h"
#include "occupancy_scans.h"

namespace metricmap {
namespace {

constexpr std::int64_t kOcto = 32768;

struct Comparison {
  std::size_t ours = 0, theirs_only = 0, ours_only = 0, both = 0, same_state = 0, same_log_odds = 0,
              union_size = 0;
};

Comparison compare(const LogOddsMap& ours, const octomap::OcTree& tree) {
  Comparison c;
  ours.forEachKnown([&](const VoxelKey& k, float l) {
    ++c.ours;
    const octomap::OcTreeNode* node = tree.search(octomap::OcTreeKey(
        static_cast<octomap::key_type>(k.x + kOcto), static_cast<octomap::key_type>(k.y + kOcto),
        static_cast<octomap::key_type>(k.z + kOcto)));
    if (node == nullptr) {
      ++c.ours_only;
      return;
    }
    ++c.both;
    c.same_state += (tree.isNodeOccupied(node) == ours.isOccupied(l)) ? 1 : 0;
    c.same_log_odds += std::abs(node->getLogOdds() - l) <= 1e-5f ? 1 : 0;
  });
  const unsigned depth = tree.getTreeDepth();
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const octomap::OcTreeKey base = it.getIndexKey();
    const std::int64_t edge = std::int64_t{1} << (depth - it.getDepth());
    for (std::int64_t z = 0; z < edge; ++z)
      for (std::int64_t y = 0; y < edge; ++y)
        for (std::int64_t x = 0; x < edge; ++x) {
          const VoxelKey k{base[0] + x - kOcto, base[1] + y - kOcto, base[2] + z - kOcto};
          if (!ours.logOdds(k)) ++c.theirs_only;
        }
  }
  c.union_size = c.ours + c.theirs_only;
  return c;
}

void insertBoth(const test::WorldScan& scan, LogOddsMap& ours, octomap::OcTree& tree,
                double max_range, double& ours_s, double& theirs_s) {
  octomap::Pointcloud pc;
  pc.reserve(scan.points.size());
  for (const auto& p : scan.points) pc.push_back(p.x, p.y, p.z);
  const octomap::point3d origin(scan.origin.x(), scan.origin.y(), scan.origin.z());
  auto t0 = std::chrono::steady_clock::now();
  tree.insertPointCloud(pc, origin, max_range, /*lazy_eval=*/false, /*discretize=*/false);
  auto t1 = std::chrono::steady_clock::now();
  ours.insertScan(scan.points, scan.origin);
  auto t2 = std::chrono::steady_clock::now();
  theirs_s += std::chrono::duration<double>(t1 - t0).count();
  ours_s += std::chrono::duration<double>(t2 - t1).count();
}

// Three real scans at 0.2 m with OctoMap's default sensor model and a 50 m max range
// (liboctomap takes ~1.7 s per scan here; the three give both fresh and repeated updates).
TEST(LogOddsOracle, KittiFramesMatchLiboctomap) {
  LogOddsParams params;
  params.resolution = 0.2;
  params.max_range = 50.0;
  LogOddsMap ours(params);
  octomap::OcTree tree(params.resolution);
  double ours_s = 0, theirs_s = 0;
  for (std::size_t frame : {0u, 2u, 4u}) {
    insertBoth(test::kittiWorldScan(frame), ours, tree, params.max_range, ours_s, theirs_s);
  }
  const Comparison c = compare(ours, tree);
  std::printf(
      "voxels: ours %zu, liboctomap-only %zu, ours-only %zu, both %zu, same state %zu, "
      "same log-odds %zu; seconds: ours %.3f liboctomap %.3f\n",
      c.ours, c.theirs_only, c.ours_only, c.both, c.same_state, c.same_log_odds, ours_s, theirs_s);
  ASSERT_GT(c.ours, 500000u);  // a real map, not an empty one agreeing with another
  const std::size_t agree = c.same_state;
  EXPECT_GE(static_cast<double>(agree), 0.999 * static_cast<double>(c.union_size));
  EXPECT_EQ(c.same_log_odds, c.both);
  // and the counts liboctomap reports for its own tree
  std::size_t occ = 0;
  const unsigned depth = tree.getTreeDepth();
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    if (tree.isNodeOccupied(*it)) occ += std::size_t{1} << (3 * (depth - it.getDepth()));
  }
  EXPECT_NEAR(static_cast<double>(ours.occupiedVoxels()), static_cast<double>(occ),
              0.001 * static_cast<double>(c.union_size));
}

// Beams from a voxel corner to voxel corners and edges: where the walk is decided by rounding.
TEST(LogOddsOracle, CornerBeamsMatchLiboctomap) {
  LogOddsParams params;
  params.resolution = 0.2;
  params.max_range = 1.0;  // some beams cut too
  LogOddsMap ours(params);
  octomap::OcTree tree(params.resolution);
  test::WorldScan scan;
  for (int x = -6; x <= 6; ++x)
    for (int y = -6; y <= 6; ++y)
      for (int z = -3; z <= 3; ++z)
        scan.points.push_back(pcl::PointXYZ(0.2f * static_cast<float>(x),
                                            0.2f * static_cast<float>(y),
                                            0.2f * static_cast<float>(z)));
  scan.origin = Eigen::Vector3f(0.4f, -0.2f, 0.0f);
  double a = 0, b = 0;
  insertBoth(scan, ours, tree, params.max_range, a, b);
  const Comparison c = compare(ours, tree);
  EXPECT_GT(c.ours, 100u);
  EXPECT_EQ(c.ours_only + c.theirs_only, 0u);
  EXPECT_EQ(c.same_log_odds, c.both);
  EXPECT_EQ(c.same_state, c.both);
}

}  // namespace
}  // namespace metricmap
