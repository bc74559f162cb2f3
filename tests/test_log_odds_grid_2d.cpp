// LogOddsGrid2D against liboctomap's OcTree::insertPointCloud on beams in one horizontal layer
// of voxels (lazy evaluation off, no discretisation): the same cells, the same float log-odds.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <octomap/OcTree.h>

#include <gtest/gtest.h>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/mapping/log_odds_grid_2d.h"
#include "shared_data.h"

namespace metricmap {
namespace {

constexpr std::int64_t kOcto = 32768;

struct Oracle {
  octomap::OcTree tree;
  float z;  // the layer's centre: beams stay inside it
  Oracle(const LogOddsParams& p) : tree(p.resolution), z(static_cast<float>(p.resolution * 0.5)) {
    tree.setProbHit(p.prob_hit);
    tree.setProbMiss(p.prob_miss);
    tree.setClampingThresMin(p.clamp_min);
    tree.setClampingThresMax(p.clamp_max);
    tree.setOccupancyThres(p.occupancy_threshold);
  }
  void insert(const Eigen::Vector2f& o, const std::vector<Eigen::Vector2f>& ends, double range) {
    octomap::Pointcloud pc;
    for (const auto& e : ends)
      if (std::isfinite(e.x()) && std::isfinite(e.y())) pc.push_back(e.x(), e.y(), z);
    tree.insertPointCloud(pc, octomap::point3d(o.x(), o.y(), z), std::isfinite(range) ? range : -1,
                          /*lazy_eval=*/false, /*discretize=*/false);
  }
};

/// Every cell of both maps: same set, same log-odds bit for bit, same state.
void expectSame(const LogOddsGrid2D& ours, const Oracle& oracle) {
  std::size_t theirs = 0, mismatched = 0, layer = 0;
  for (auto it = oracle.tree.begin_leafs(), end = oracle.tree.end_leafs(); it != end; ++it) {
    ASSERT_EQ(it.getDepth(), oracle.tree.getTreeDepth()) << "a pruned node in a single layer";
    const octomap::OcTreeKey k = it.getKey();
    layer += k[2] == kOcto ? 1 : 0;
    ++theirs;
    const std::int64_t i = k[0] - kOcto, j = k[1] - kOcto;
    const bool occupied = oracle.tree.isNodeOccupied(*it);
    const CellState s = ours.state(i, j);
    if (s == CellState::Unknown || ours.logOdds(i, j) != it->getLogOdds() ||
        (s == CellState::Occupied) != occupied) {
      if (++mismatched <= 5)
        ADD_FAILURE() << "cell " << i << "," << j << ": octomap " << it->getLogOdds() << ", ours "
                      << ours.logOdds(i, j) << " state " << static_cast<int>(s);
    }
  }
  EXPECT_EQ(layer, theirs) << "the oracle left the layer";
  EXPECT_EQ(mismatched, 0u);
  EXPECT_EQ(ours.knownCells(), theirs);
  EXPECT_GT(theirs, 0u);
}

TEST(LogOddsGrid2D, EqualsOctomapOnRandomScans) {
  for (const double range : {std::numeric_limits<double>::infinity(), 6.0}) {
    LogOddsParams p;
    p.resolution = 0.1;
    p.max_range = range;
    LogOddsGrid2D ours(p);
    Oracle oracle(p);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> pos(-4.0f, 4.0f), far(-12.0f, 12.0f);
    for (int scan = 0; scan < 40; ++scan) {
      const Eigen::Vector2f o(pos(rng), pos(rng));
      std::vector<Eigen::Vector2f> ends;
      for (int b = 0; b < 300; ++b) ends.emplace_back(far(rng), far(rng));
      // beams along the axes, ends on cell borders, in the origin's cell, a repeated end
      ends.emplace_back(o.x() + 3.0f, o.y());
      ends.emplace_back(o.x(), o.y() - 2.5f);
      ends.emplace_back(1.0f, -2.0f);
      ends.emplace_back(0.0f, 0.3f);
      ends.emplace_back(o.x() + 0.01f, o.y());
      ends.emplace_back(1.0f, -2.0f);
      ends.emplace_back(std::nanf(""), 1.0f);
      ours.insertScan(o, ends);
      oracle.insert(o, ends, range);
      // diagonals from a cell's centre: every crossing a tie between the axes
      const float v = 0.05f + 0.1f * static_cast<float>(scan % 7 - 3);
      const Eigen::Vector2f c(v, v);  // the same arithmetic on both axes: exact ties
      ends.clear();
      for (const float d : {2.0f, -1.5f}) {
        ends.emplace_back(c.x() + d, c.y() + d);
        ends.emplace_back(c.x() + d, c.y() - d);
      }
      ours.insertScan(c, ends);
      oracle.insert(c, ends, range);
    }
    SCOPED_TRACE(range);
    expectSame(ours, oracle);
    EXPECT_GT(ours.occupiedCells(), 0u);
    EXPECT_GT(ours.freeCells(), 0u);
  }
}

TEST(LogOddsGrid2D, EqualsOctomapOnTheIntelLog) {
  const std::string log = std::string(METRICMAP_SHARED_DATA_DIR) + "/radish_clf_raw/intel.clf.bz2";
  SKIP_WITHOUT_SHARED_DATA(log);
  auto source = openScanSource(log);
  LogOddsParams p;
  p.resolution = 0.05;
  p.max_range = 20.0;
  LogOddsGrid2D ours(p);
  Oracle oracle(p);
  for (std::size_t i = 0; i < 120; ++i) {
    const Scan s = source->scan(i);
    ASSERT_TRUE(s.odometry.has_value());
    const Eigen::Isometry3d& pose = *s.odometry;
    std::vector<Eigen::Vector2f> ends;
    for (const auto& q : s.points) {
      const Eigen::Vector3d w = pose * q.getVector3fMap().cast<double>();
      ends.emplace_back(static_cast<float>(w.x()), static_cast<float>(w.y()));
    }
    const Eigen::Vector2f o(static_cast<float>(pose.translation().x()),
                            static_cast<float>(pose.translation().y()));
    ours.insertScan(o, ends);
    oracle.insert(o, ends, p.max_range);
  }
  expectSame(ours, oracle);
  EXPECT_EQ(ours.scans(), 120u);
}

TEST(LogOddsGrid2D, ImagesFollowMapServer) {
  LogOddsParams p;
  p.resolution = 0.5;
  LogOddsGrid2D g(p);
  EXPECT_THROW(g.trinaryImage(), std::invalid_argument);
  g.insertScan({0.25f, 0.25f}, {{2.25f, 0.25f}});  // cells 0,1,2,3 free; 4 hit
  const MapServerImage t = g.trinaryImage();
  ASSERT_EQ(t.width, 5);
  ASSERT_EQ(t.height, 1);
  EXPECT_EQ(t.mode, MapServerMode::Trinary);
  EXPECT_DOUBLE_EQ(t.origin_x, 0.0);
  EXPECT_EQ(t.pixels, (std::vector<std::uint8_t>{254, 254, 254, 254, 0}));
  g.insertScan({0.25f, 0.25f}, {{0.25f, 1.25f}});  // a column: cells (0,1) free, (0,2) hit
  const MapServerImage q = g.probabilityImage();
  ASSERT_EQ(q.width, 5);
  ASSERT_EQ(q.height, 3);
  EXPECT_EQ(q.mode, MapServerMode::Scale);
  // row 0 is the top (j = 2): (0,2) hit once, the rest of that row unknown (the prior)
  auto grey = [](float l) {
    return static_cast<std::uint8_t>(std::lround(255 * (1 - probabilityOf(l))));
  };
  EXPECT_EQ(q.pixels[0], grey(logOddsOf(0.7)));
  EXPECT_NEAR(q.pixels[0], 255 * 0.3, 0.51);
  EXPECT_EQ(q.pixels[1], 127);
  // (0,0) crossed twice: p = 0.4^2 / (0.4^2 + 0.6^2)
  const double p00 = 0.16 / (0.16 + 0.36);
  EXPECT_EQ(q.pixels[2 * 5 + 0], grey(logOddsOf(0.4) + logOddsOf(0.4)));
  EXPECT_NEAR(q.pixels[2 * 5 + 0], 255 * (1 - p00), 0.51);
  EXPECT_EQ(g.occupiedCells(), 2u);
  EXPECT_EQ(g.knownCells(), 7u);
}

TEST(LogOddsGrid2D, RefusesWhatItCannotHold) {
  LogOddsParams p;
  p.resolution = 1e-4;
  LogOddsGrid2D g(p);
  EXPECT_THROW(g.insertScan({0, 0}, {{1e6f, 0}}), CapacityError);       // beyond 2^30 cells
  EXPECT_THROW(g.insertScan({0, 0}, {{50.0f, 50.0f}}), CapacityError);  // 2.5e11 cells
  EXPECT_EQ(g.knownCells(), 0u);
  EXPECT_THROW(g.insertScan({std::nanf(""), 0}, {{1, 1}}), CapacityError);
  p.resolution = 0;
  EXPECT_THROW(LogOddsGrid2D{p}, std::invalid_argument);
}

}  // namespace
}  // namespace metricmap
