// The memory budget over a whole run, not each allocation alone: a 2D SLAM run whose odometry
// jumps 100 m per scan grows its submap grids, loop-closure levels and final map; each growth is
// priced beside what the run already holds (it peaked at 2.5x the budget). A depth image's cloud
// is priced before it exists. A pose that is a reflection is refused where frames are added.
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/mapping/height_map.h"
#include "metricmap/slam/slam_2d.h"

namespace metricmap {
namespace {

/// Sets the process's budget for one test, restores it after.
struct BudgetScope {
  std::uint64_t saved = memoryBudget();
  explicit BudgetScope(std::uint64_t bytes) { setMemoryBudget(bytes); }
  ~BudgetScope() { setMemoryBudget(saved); }
};

LaserScan corridor() {
  LaserScan s;
  for (int k = 0; k < 180; ++k) {
    s.angles.push_back(-M_PI / 2 + M_PI * k / 179.0);
    s.ranges.push_back(4.0 + 0.5 * std::sin(0.2 * k));
  }
  return s;
}

TEST(RunBudget, Slam2DWithHugeOdometryJumpsStopsAtTheBudgetNotBeyond) {
  const std::uint64_t budget = std::uint64_t{48} << 20;
  BudgetScope scope(budget);
  Slam2D slam{Slam2DConfig{}};
  std::size_t added = 0;
  try {
    for (int k = 0; k < 200; ++k) {
      slam.addScan(corridor(), Pose2D{100.0 * k, 0, 0}, 0.1 * k);
      ++added;
    }
    slam.finish();
    ADD_FAILURE() << "200 scans 100 m apart fit in 48 MiB";
  } catch (const CapacityError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("already held, more than the memory budget of 48 MiB"), std::string::npos)
        << w;
  }
  // The oracle: a full submap grid spans its scans 100 m apart at 0.05 m cells, 8 bytes a cell,
  // far beyond 48 MiB; the run stops after a few scans, with the message above.
  const double one_grid_bytes = (100.0 * Slam2DConfig{}.scans_per_submap / 0.05) * 180 * 8;
  std::cout << "refused after " << added
            << " scans; one full submap grid: " << one_grid_bytes / (1 << 20) << " MiB\n";
  EXPECT_GT(added, 2u);
}

TEST(RunBudget, DepthCloudsArePricedBeforeTheyExist) {
  DepthImage depth;
  depth.width = 1000;
  depth.height = 1000;
  depth.values.assign(1000000, 1000);
  const CameraIntrinsics k{500, 500, 500, 500, 1000, 1000, 0};
  {
    BudgetScope scope(std::uint64_t{8} << 20);  // 16 MB of PointXYZ do not fit
    try {
      depthToCloud(depth, k, 0.001);
      ADD_FAILURE() << "built";
    } catch (const CapacityError& e) {
      EXPECT_NE(std::string(e.what()).find("1000 x 1000 depth image"), std::string::npos)
          << e.what();
    }
  }
  BudgetScope scope(std::uint64_t{32} << 20);
  EXPECT_EQ(depthToCloud(depth, k, 0.001).size(), 1000000u);
}

TEST(RunBudget, HeightMapRefusesAReflectionAsAPose) {
  HeightMapParams p;
  p.map_size = 64;
  HeightMap map(p);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back({0.1f, 0.2f, 0.5f});
  for (const Eigen::Vector3d& d : {Eigen::Vector3d(1, 1, -1), Eigen::Vector3d(2, 2, 2),
                                   Eigen::Vector3d(-1, 1, 1), Eigen::Vector3d(0, 0, 0)}) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = d.asDiagonal();
    EXPECT_THROW(map.addFrame(cloud, pose), std::invalid_argument) << d.transpose();
  }
  EXPECT_EQ(map.statistics().valid_points, 0u);
  map.addFrame(cloud, Eigen::Isometry3d::Identity());
  EXPECT_EQ(map.statistics().valid_points, 1u);
}

}  // namespace
}  // namespace metricmap
