// The relation metric on an estimate whose stamps step back (raw logs deliver scans out of
// order): each relation's stamps find their own poses; the metric equals the one of the same
// poses given in stamp order.
#include <cmath>

#include <gtest/gtest.h>

#include "metricmap/common/pose_2d_spatial.h"
#include "metricmap/evaluation/relation_error.h"
#include "metricmap/evaluation/trajectory_order.h"

namespace metricmap {
namespace {

Eigen::Isometry3d planar(double x, double y, double yaw) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() << x, y, 0;
  t.linear() = Eigen::Matrix3d(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return t;
}

TEST(RelationError, StampsThatStepBackFindTheirOwnPoses) {
  Trajectory shuffled;
  shuffled.stamps = {0.0, 2.0, 1.0, 3.0};
  shuffled.poses = {planar(0, 0, 0), planar(2, 0, 0.2), planar(1, 0, 0.1), planar(3, 1, 0.3)};
  Trajectory ordered;
  ordered.stamps = {0.0, 1.0, 2.0, 3.0};
  ordered.poses = {shuffled.poses[0], shuffled.poses[2], shuffled.poses[1], shuffled.poses[3]};
  std::vector<PoseRelation> rel(3);
  rel[0] = {1.0, 3.0, planar(1, 0, 0.1).inverse() * planar(3, 1, 0.3)};  // exact: error 0
  rel[1] = {0.0, 2.0, planar(2.5, 0, 0.2)};                              // 0.5 m off in x
  rel[2] = {2.0, 1.0, planar(-1, 0.3, -0.1)};                            // backwards in time
  const RelationError a = relationError(shuffled, rel, 1e-6);
  const RelationError b = relationError(ordered, rel, 1e-6);
  ASSERT_EQ(a.used, 3u);
  EXPECT_NEAR(a.translation[0], 0.0, 1e-12);
  EXPECT_NEAR(a.translation[1], 0.5, 1e-12);
  // relation 2: truth (-1, 0.3) in pose 2's frame; the estimate's is pose(2)^-1 pose(1)
  const Eigen::Isometry3d d = planar(2, 0, 0.2).inverse() * planar(1, 0, 0.1);
  EXPECT_NEAR(a.translation[2], (planar(-1, 0.3, -0.1).inverse() * d).translation().norm(), 1e-12);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(a.translation[k], b.translation[k]);
    EXPECT_DOUBLE_EQ(a.rotation_deg[k], b.rotation_deg[k]);
  }
  shuffled.stamps[2] = std::nan("");
  EXPECT_THROW(relationError(shuffled, rel, 1e-6), std::invalid_argument);
}

TEST(RelationError, TrajectoryInStampOrderAndPlanarPoses) {
  Trajectory t;
  t.stamps = {3.0, 1.0, 2.0};
  t.poses = {spatialPose({3, 0, 0.3}), spatialPose({1, 0, 0.1}), spatialPose({2, 0, -3.0})};
  EXPECT_EQ(stampOrder(t), (std::vector<std::size_t>{1, 2, 0}));
  const Trajectory s = inStampOrder(t);
  EXPECT_EQ(s.stamps, (std::vector<double>{1.0, 2.0, 3.0}));
  for (std::size_t k = 0; k < 3; ++k) {
    const Pose2D p = planarPose(s.poses[k]);
    EXPECT_NEAR(p.x, s.stamps[k], 1e-15);
    EXPECT_NEAR(p.theta, k == 1 ? -3.0 : 0.1 * s.stamps[k], 1e-15);
    EXPECT_NEAR(s.poses[k].translation().z(), 0.0, 0.0);
  }
  t.stamps[2] = 1.0;
  try {
    inStampOrder(t);
    FAIL() << "two poses with one stamp were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "poses 1 and 2 have the same stamp");
  }
  EXPECT_THROW(inStampOrder(Trajectory{{}, t.poses}), std::invalid_argument);
}

// A relation stamp the estimate lacks is placed by the odometry from the nearest estimated pose
// (Kümmerle et al.'s metricEvaluator): P(t) = P(t_n) O(t_n)^-1 O(t), hand-computed here.
TEST(RelationError, OdometryPlacesStampsTheEstimateLacks) {
  Trajectory estimate;
  estimate.stamps = {0.0, 10.0};
  estimate.poses = {planar(0, 0, 0), planar(5, 5, 1.0)};
  Trajectory odometry;  // a different world frame: only its motion counts
  odometry.stamps = {0.0, 1.0, 2.0, 4.0};
  odometry.poses = {planar(10, 0, 0), planar(10, 1, M_PI / 2), planar(10, 1, M_PI / 2),
                    planar(12, 1, M_PI)};
  std::vector<PoseRelation> rel(4);
  // t = 1: the odometry moved (0, 1) and turned 90 degrees from t = 0: P(1) = (0, 1, 90 deg).
  rel[0] = {0.0, 1.0, planar(0, 1.5, M_PI / 2)};  // 0.5 m off, no turn
  // t = 3: halfway between the odometry's t = 2 and t = 4: (11, 1) at 135 degrees; P(0) is the
  // identity, so P(3) = O(0)^-1 O(3).
  const Eigen::Isometry3d o3 = planar(11, 1, 0.75 * M_PI);
  const Eigen::Isometry3d p3 = planar(10, 0, 0).inverse() * o3;
  rel[1] = {0.0, 3.0, p3 * planar(0, 0, 5.0 * M_PI / 180)};  // true: 5 degrees more turn
  rel[2] = {0.0, 4.5, planar(0, 0, 0)};     // beyond the odometry by 0.5 s: skipped
  rel[3] = {0.0, 10.0, planar(5, 5, 1.0)};  // both stamps in the estimate: exact
  const RelationError e = relationError(estimate, rel, 0.1, &odometry);
  ASSERT_EQ(e.used, 3u);
  ASSERT_EQ(e.skipped, std::vector<std::size_t>{2});
  EXPECT_NEAR(e.translation[0], 0.5, 1e-12);
  EXPECT_NEAR(e.rotation_deg[0], 0.0, 1e-9);
  EXPECT_NEAR(e.translation[1], 0.0, 1e-12);
  EXPECT_NEAR(e.rotation_deg[1], 5.0, 1e-9);
  EXPECT_NEAR(e.translation[2], 0.0, 1e-12);
  EXPECT_EQ(e.interpolated, 2u);
  // Without odometry, only the relation whose stamps the estimate has counts.
  const RelationError plain = relationError(estimate, rel, 0.1);
  EXPECT_EQ(plain.used, 1u);
  // The pose at a stamp: interpolated, clamped within the tolerance, none beyond it.
  const auto mid = poseAtStamp(odometry, 3.0, 0.1);
  ASSERT_TRUE(mid);
  EXPECT_TRUE(mid->isApprox(o3, 1e-12));
  EXPECT_TRUE(poseAtStamp(odometry, 4.05, 0.1)->isApprox(odometry.poses[3], 1e-12));
  EXPECT_FALSE(poseAtStamp(odometry, 4.2, 0.1));
  odometry.stamps[1] = INFINITY;
  EXPECT_THROW(relationError(estimate, rel, 0.1, &odometry), std::invalid_argument);
}

}  // namespace
}  // namespace metricmap
