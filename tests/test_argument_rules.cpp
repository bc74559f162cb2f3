// Rules the library applies to arguments the Python module (and any caller) hands it: one 2D
// scan order, restorable 2D grids, TUM stamps that read back, non-finite values refused, and
// the options a source would ignore.
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/evaluation/trajectory.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/mapping/height_map.h"
#include "metricmap/mapping/log_odds_grid_2d.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/slam/slam_2d.h"

namespace {

using namespace metricmap;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ArgumentRules, LaserScanAnglesFirst) {
  LaserScan scan{{-1.0, 0.0, 1.0}, {2.0, 7.5, 3.0}};
  EXPECT_NO_THROW(validateLaserScan(scan));
  std::swap(scan.angles, scan.ranges);  // 7.5 "rad": a range in the angles' place
  EXPECT_THROW(validateLaserScan(scan), std::invalid_argument);
  EXPECT_THROW(validateLaserScan({{0.0, kNaN}, {1.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(validateLaserScan({{0.0}, {1.0, 1.0}}), std::invalid_argument);
  EXPECT_NO_THROW(validateLaserScan({}));
  Slam2D slam{Slam2DConfig{}};
  EXPECT_THROW(slam.addScan(LaserScan{}, std::nullopt), std::invalid_argument);
  EXPECT_THROW(slam.addScan({{0.0}, {1.0}}, std::nullopt, kInf), std::invalid_argument);
}

TEST(ArgumentRules, SavedGridEqualsTheGrid) {
  LogOddsGrid2D grid{LogOddsParams{}};
  grid.insertScan({0.0f, 0.0f}, {{1.0f, 0.5f}, {-0.7f, 1.2f}, {0.3f, -2.0f}});
  const std::vector<float> cells(grid.data(), grid.data() + grid.width() * grid.height());
  const LogOddsGrid2D back(grid.params(), grid.minI(), grid.minJ(), grid.width(), grid.height(),
                           cells);
  ASSERT_EQ(back.knownCells(), grid.knownCells());
  EXPECT_EQ(back.occupiedCells(), grid.occupiedCells());
  for (std::int64_t j = grid.minJ(); j < grid.minJ() + grid.height(); ++j)
    for (std::int64_t i = grid.minI(); i < grid.minI() + grid.width(); ++i) {
      ASSERT_EQ(back.state(i, j), grid.state(i, j));
      ASSERT_EQ(back.logOdds(i, j), grid.logOdds(i, j));
    }
  EXPECT_THROW(LogOddsGrid2D(grid.params(), 0, 0, 2, 2, std::vector<float>(3)),
               std::invalid_argument);
  EXPECT_THROW(LogOddsGrid2D(grid.params(), 0, 0, 1, 1, {static_cast<float>(kInf)}),
               std::invalid_argument);
}

TEST(ArgumentRules, TumStampsReadBack) {
  Trajectory t;
  t.poses.assign(3, Eigen::Isometry3d::Identity());
  for (const std::vector<double>& bad :
       {std::vector<double>{0.0, 2.0, 1.0}, {0.0, 1.0, 1.0 + 1e-12}, {0.0, kNaN, 2.0}}) {
    t.stamps = bad;
    EXPECT_THROW(formatTumTrajectory(t), std::invalid_argument);
  }
  t.stamps = {0.0, 1.0, 2.0};
  EXPECT_NO_THROW(formatTumTrajectory(t));
}

TEST(ArgumentRules, NonFiniteValues) {
  EXPECT_THROW(cameraToMap(kNaN, 0.1, 0.0), std::invalid_argument);
  EXPECT_THROW(cameraToMap(1.0, kInf, 0.0), std::invalid_argument);
  EXPECT_THROW(cameraToMap(1.0, 0.1, kNaN), std::invalid_argument);
  // The CLI's --pitch-deg (+-90) and --yaw-deg (+-360) bounds, in the library for both fronts.
  EXPECT_THROW(cameraToMap(1.0, 1e17, 0.0), std::invalid_argument);
  EXPECT_THROW(cameraToMap(1.0, -M_PI / 2 - 1e-9, 0.0), std::invalid_argument);
  EXPECT_THROW(cameraToMap(1.0, 0.1, 1e30), std::invalid_argument);
  EXPECT_NO_THROW(cameraToMap(1.0, 90.0 * (M_PI / 180.0), -360.0 * (M_PI / 180.0)));
  LidarOdometryConfig c;
  c.deskew = true;
  c.min_range = 0.0;
  LidarOdometry odometry(c);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 200; ++k)
    points.emplace_back(std::cos(k * 0.1) * 5, std::sin(k * 0.1) * 5, 0.1 * (k % 7));
  std::vector<double> times(points.size(), 0.5);
  times[0] = kInf;
  EXPECT_THROW(odometry.registerFrame(points, times), std::invalid_argument);
  points[0] = Eigen::Vector3d::Constant(kNaN);  // a skipped point's time does not matter
  EXPECT_NO_THROW(odometry.registerFrame(points, times));
}

TEST(ArgumentRules, IgnoredSourceOptions) {
  EXPECT_NE(ignoredSourceOption("folder", "sequence"), "");
  EXPECT_NE(ignoredSourceOption("carmen", "times"), "");
  EXPECT_NE(ignoredSourceOption("carmen", "reference_poses"), "");
  EXPECT_NE(ignoredSourceOption("bag", "times"), "");
  EXPECT_NE(ignoredSourceOption("kitti", "topic"), "");
  EXPECT_EQ(ignoredSourceOption("kitti", "sequence"), "");
  EXPECT_EQ(ignoredSourceOption("bag", "topic"), "");
  EXPECT_EQ(ignoredSourceOption("folder", "times"), "");
  EXPECT_EQ(ignoredSourceOption("", "sequence"), "");
}

}  // namespace
