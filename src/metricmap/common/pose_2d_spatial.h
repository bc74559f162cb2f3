#pragma once
/// \file pose_2d_spatial.h
/// \brief Planar poses as 3D transforms and back: a 2D estimate written where trajectories are
/// 3D (TUM files, the evaluation), a 3D pose read where a planar one is needed.

#include <cmath>

#include <Eigen/Geometry>

#include "metricmap/common/pose_2d.h"

namespace metricmap {

/// \brief (x, y, 0) and a rotation of theta about z.
inline Eigen::Isometry3d spatialPose(const Pose2D& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() << p.x, p.y, 0.0;
  t.linear() = Eigen::Matrix3d(Eigen::AngleAxisd(p.theta, Eigen::Vector3d::UnitZ()));
  return t;
}

/// \brief The transform's x, y and its heading atan2(R10, R00) (z, roll and pitch dropped).
inline Pose2D planarPose(const Eigen::Isometry3d& t) {
  return {t.translation().x(), t.translation().y(), std::atan2(t(1, 0), t(0, 0))};
}

}  // namespace metricmap
