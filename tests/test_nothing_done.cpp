// Nothing done is never reported as a result, and nothing the toolkit writes is refused by its
// own reader: a relation metric over no relation (mean 0.0 read as perfect), a pose graph without
// edges ("converged"), a TUM trajectory whose stamps do not increase as written.
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "metricmap/evaluation/relation_error.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/posegraph/optimize.h"
#include "temp_dir.h"

namespace metricmap {
namespace {

Eigen::Isometry3d planar(double x, double y, double yaw) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = Eigen::Vector3d(x, y, 0);
  p.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return p;
}

TEST(NothingDone, RelationErrorOverNoMatchedRelationIsRefused) {
  Trajectory est;
  for (int k = 0; k < 4; ++k) {
    est.stamps.push_back(k);
    est.poses.push_back(planar(k, 0, 0));
  }
  struct Case {
    std::vector<PoseRelation> relations;
    std::size_t used;  ///< 0: refused
  };
  const std::vector<Case> cases = {
      {{{10.0, 11.0, planar(1, 0, 0)}}, 0},
      {{{0.5, 1.5, planar(1, 0, 0)}, {2.0, 9.0, planar(7, 0, 0)}}, 0},
      {{{0.0, 1.0, planar(1, 0, 0)}, {2.0, 9.0, planar(7, 0, 0)}}, 1},
      {{{0.0, 3.0, planar(3, 0, 0)}}, 1},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.relations.size());
    if (c.used == 0) {
      try {
        relationError(est, c.relations);
        ADD_FAILURE() << "a result over no relation";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("nothing to measure"), std::string::npos) << e.what();
      }
    } else {
      const RelationError e = relationError(est, c.relations);
      EXPECT_EQ(e.used, c.used);
      EXPECT_NEAR(e.translation_abs.mean, 0.0, 1e-12);  // the relations are the estimate's
    }
  }
}

TEST(NothingDone, OptimizingAGraphWithoutEdgesIsRefused) {
  for (std::size_t vertices : {0u, 1u, 2u, 5u}) {
    SCOPED_TRACE(vertices);
    PoseGraph2D g;
    for (std::size_t i = 0; i < vertices; ++i)
      g.addVertex(static_cast<std::int64_t>(i), Pose2D{double(i), 0, 0});
    try {
      optimize(g);
      ADD_FAILURE() << "optimised a graph without edges";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::to_string(vertices) + " vertices and no edge"),
                std::string::npos)
          << e.what();
    }
    PoseGraph3D g3;
    for (std::size_t i = 0; i < vertices; ++i) g3.addVertex(static_cast<std::int64_t>(i), {});
    EXPECT_THROW(optimize(g3), std::invalid_argument);
  }
  // One edge: optimised, and converged on a consistent graph.
  PoseGraph2D g;
  g.addVertex(0, Pose2D{0, 0, 0});
  g.addVertex(1, Pose2D{1.5, 0.2, 0.1});
  g.addEdge(0, 1, Pose2D{1, 0, 0}, PoseGraph2D::Information::Identity());
  const PoseGraphOptimizeResult r = optimize(g);
  EXPECT_EQ(r.termination, PoseGraphTermination::Converged);
  EXPECT_NEAR(g.vertex(1).pose.x, 1.0, 1e-6);
}

struct StampCase {
  std::vector<double> stamps;
  bool refused;
};

TEST(NothingDone, TumTrajectoriesTheReaderWouldRefuseAreNotWritten) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<StampCase> cases = {
      {{0, 2, 1}, true},
      {{0, 1, 1}, true},
      {{0, 1e-10, 1}, true},  // distinct, but equal as written (%.9f)
      {{5, 4}, true},
      {{0, nan, 2}, true},
      {{0, 1, std::numeric_limits<double>::infinity()}, true},
      {{0, 1e-9, 1}, false},
      {{-3, 0, 1e9}, false},
      {{1317384588.915486, 1317384589.015486, 1317384589.115486}, false},
  };
  TempDir dir("tum_write");
  for (const StampCase& c : cases) {
    SCOPED_TRACE(testing::Message() << c.stamps[0] << ", " << c.stamps[1]);
    Trajectory t;
    t.stamps = c.stamps;
    for (std::size_t k = 0; k < c.stamps.size(); ++k) t.poses.push_back(planar(k, 1, 0.1 * k));
    if (c.refused) {
      EXPECT_THROW(formatTumTrajectory(t), std::invalid_argument);
      continue;
    }
    const std::string path = dir.write("t.txt", formatTumTrajectory(t));
    // The oracle: the toolkit's reader takes it back, stamps within the 1e-9 s written.
    const Trajectory back = readTrajectoryFile(path, TrajectoryFormat::Tum);
    ASSERT_EQ(back.stamps.size(), c.stamps.size());
    for (std::size_t k = 0; k < c.stamps.size(); ++k)
      EXPECT_NEAR(back.stamps[k], c.stamps[k], 1e-9 + 1e-15 * std::fabs(c.stamps[k]));
  }
}

TEST(NothingDone, PosesTheReadersWouldRefuseAreNotWritten) {
  Trajectory t;
  t.poses = {planar(0, 0, 0), planar(2e6, 0, 0)};  // beyond the readers' 1e6 m bound
  EXPECT_THROW(formatTumTrajectory(t), std::invalid_argument);
  EXPECT_THROW(formatKittiTrajectory(t), std::invalid_argument);
  t.poses[1] = planar(1, 0, 0);
  t.poses[1].linear() *= 2.0;  // not a rotation
  EXPECT_THROW(formatKittiTrajectory(t), std::invalid_argument);
  t.poses[1] = planar(1e6, -1e6, 3);
  TempDir dir("kitti_write");
  EXPECT_EQ(readTrajectoryFile(dir.write("k.txt", formatKittiTrajectory(t))).size(), 2u);
  EXPECT_EQ(readTrajectoryFile(dir.write("t.txt", formatTumTrajectory(t))).size(), 2u);
}

}  // namespace
}  // namespace metricmap
