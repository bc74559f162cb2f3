// The relation metric on an estimate whose stamps step back (raw logs deliver scans out of
// order): each relation's stamps find their own poses; the metric equals the one of the same
// poses given in stamp order.
#include <cmath>

#include <gtest/gtest.h>

#include "metricmap/evaluation/relation_error.h"

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

}  // namespace
}  // namespace metricmap
