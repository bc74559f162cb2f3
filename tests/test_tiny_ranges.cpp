// Tiny beam cuts and beam ends within rounding of the sensor: every configuration that carries a
// log-odds max_range refuses one below 1 mm, and a beam whose end is closer to the origin than a
// float direction can resolve is cast as ending at the origin (no walk that never ends).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>

#include <gtest/gtest.h>

#include "metricmap/mapping/log_odds_grid_2d.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/sequence/scan_mapper.h"
#include "metricmap/slam/slam_2d_config.h"

namespace metricmap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct RangeCase {
  double max_range;
  bool accepted;
};

const std::vector<RangeCase> kRanges = {
    {1e-30, false}, {1e-23, false}, {1e-19, false}, {1e-6, false}, {9.99e-4, false},
    {0.0, false},   {-1.0, false},  {-kInf, false}, {kNaN, false}, {1e-3, true},
    {0.05, true},   {30.0, true},   {kInf, true}};

/// Runs `make` for every case: accepted values construct, refused ones throw
/// std::invalid_argument whose message names `name`.
template <typename Make>
void expectRangeRule(const std::string& name, Make make) {
  for (const RangeCase& c : kRanges) {
    SCOPED_TRACE(name + " = " + std::to_string(c.max_range));
    if (c.accepted) {
      EXPECT_NO_THROW(make(c.max_range));
    } else {
      try {
        make(c.max_range);
        ADD_FAILURE() << "accepted";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      }
    }
  }
}

TEST(TinyRanges, EveryConfigurationWithALogOddsCutRefusesBelowOneMillimetre) {
  expectRangeRule("max_range", [](double r) {
    LogOddsParams p;
    p.max_range = r;
    LogOddsMap map(p);
  });
  expectRangeRule("max_range", [](double r) {
    LogOddsParams p;
    p.max_range = r;
    LogOddsGrid2D grid(p);
  });
  expectRangeRule("map_max_range", [](double r) {
    Slam2DConfig c;
    c.map.max_range = r;
    validateSlam2DConfig(c);
  });
  expectRangeRule("max_range", [](double r) {
    ScanMapperConfig c;
    LogOddsParams p;
    p.max_range = r;
    c.occupancy = p;
    validateScanMapperConfig(c);
  });
  expectRangeRule("max_range", [](double r) {
    ScanMapperConfig c;
    c.occupancy_2d = Occupancy2DConfig{};
    c.occupancy_2d->params.max_range = r;
    validateScanMapperConfig(c);
  });
}

/// Offsets from the origin whose float square underflows: each end lies within 1e-18 m of the
/// sensor, some of them in a neighbouring voxel (the origin sits on a voxel corner).
const std::vector<Eigen::Vector3f> kNearOrigin = {
    {-1e-30f, 0, 0},       {0, -1e-25f, 0},           {-1e-30f, -1e-30f, -1e-30f},
    {1e-20f, -1e-20f, 0},  {-3e-19f, 2e-19f, 1e-30f}, {0, 0, -1e-38f},
    {-1e-45f, -1e-45f, 0}, {1e-30f, 1e-30f, 1e-30f}};

TEST(TinyRanges, EndsWithinRoundingOfTheOriginAreCastAsTheOrigin3D) {
  for (const double cut : {kInf, 1e-3, 5.0}) {
    for (const Eigen::Vector3f& d : kNearOrigin) {
      SCOPED_TRACE(testing::Message() << "offset " << d.transpose() << " cut " << cut);
      LogOddsParams p;
      p.max_range = cut;
      // A beam to (2, 0.3, 0.1) beside the tiny one: the map must still take the rest.
      pcl::PointCloud<pcl::PointXYZ> cloud, oracle_cloud;
      cloud.push_back({d.x(), d.y(), d.z()});
      cloud.push_back({2.0f, 0.3f, 0.1f});
      oracle_cloud.push_back({0, 0, 0});
      oracle_cloud.push_back({2.0f, 0.3f, 0.1f});
      LogOddsMap map(p), oracle(p);
      map.insertScan(cloud, Eigen::Vector3f::Zero());
      oracle.insertScan(oracle_cloud, Eigen::Vector3f::Zero());
      EXPECT_EQ(map.knownVoxels(), oracle.knownVoxels());
      std::size_t same = 0;
      oracle.forEachKnown([&](const VoxelKey& k, float l) {
        const auto ours = map.logOdds(k);
        same += ours && *ours == l ? 1 : 0;
      });
      EXPECT_EQ(same, oracle.knownVoxels());
    }
  }
}

TEST(TinyRanges, EndsWithinRoundingOfTheOriginAreCastAsTheOrigin2D) {
  for (const double cut : {kInf, 1e-3, 5.0}) {
    for (const Eigen::Vector3f& d : kNearOrigin) {
      SCOPED_TRACE(testing::Message() << "offset " << d.transpose() << " cut " << cut);
      LogOddsParams p;
      p.max_range = cut;
      LogOddsGrid2D grid(p), oracle(p);
      grid.insertScan(Eigen::Vector2f::Zero(), {{d.x(), d.y()}, {2.0f, 0.3f}});
      oracle.insertScan(Eigen::Vector2f::Zero(), {{0.0f, 0.0f}, {2.0f, 0.3f}});
      ASSERT_EQ(grid.knownCells(), oracle.knownCells());
      std::size_t same = 0;
      oracle.forEachKnown([&](std::int64_t i, std::int64_t j, float l) {
        same += grid.logOdds(i, j) == l ? 1 : 0;
      });
      EXPECT_EQ(same, oracle.knownCells());
    }
  }
}

}  // namespace
}  // namespace metricmap
