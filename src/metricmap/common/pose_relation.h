#pragma once
/// \file pose_relation.h
/// \brief A relation of the SLAM benchmark of Kümmerle et al. (2009): the true relative pose
/// between the sensor at two time stamps.

#include <Eigen/Geometry>

namespace metricmap {

/// \brief The sensor's pose at `stamp2` in its frame at `stamp1` (T_1^-1 * T_2 of the true
/// sensor -> world poses).
struct PoseRelation {
  double stamp1 = 0.0;  ///< seconds
  double stamp2 = 0.0;  ///< seconds
  Eigen::Isometry3d relative = Eigen::Isometry3d::Identity();
};

}  // namespace metricmap
