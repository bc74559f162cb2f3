#pragma once
/// \file rotation_angle.h
/// \brief The angle of a rotation, the one number every rotational error here is made of.

#include <Eigen/Core>

namespace metricmap {

/// \brief The rotation angle of `r` in radians, in [0, pi]: atan2(|vee(R - R^T)| / 2,
/// (trace R - 1) / 2), which equals acos((trace R - 1) / 2) (evo's and the KITTI devkit's
/// formula) but keeps its precision for small angles.
double rotationAngle(const Eigen::Matrix3d& r);

/// \brief rotationAngle in degrees.
double rotationAngleDeg(const Eigen::Matrix3d& r);

}  // namespace metricmap
