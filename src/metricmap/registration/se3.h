#pragma once
/// \file se3.h
/// \brief Exponential and logarithm of rigid motions, twist = (translation, rotation vector).

#include <Eigen/Geometry>

namespace metricmap {

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// \brief Rigid motion of the twist (v, w): rotation exp([w]x), translation V(w) v.
Eigen::Isometry3d se3Exp(const Vector6d& twist);
/// \brief Inverse of se3Exp for rotations below pi.
Vector6d se3Log(const Eigen::Isometry3d& t);

}  // namespace metricmap
