#pragma once
/// \file rigid_transform.h
/// \brief One check for every pose read from a file or an option: a proper rotation and a
/// finite, bounded translation. A zero matrix or a 1e308 translation would otherwise drop or
/// collapse every point it moves.

#include <string>

#include <Eigen/Core>

namespace metricmap {

/// \brief Largest |R^T R - I| entry and |det R - 1| accepted: KITTI's Tr is orthonormal to
/// ~1e-7, pose files printed with 6 significant digits to ~1e-6.
constexpr double kRotationTolerance = 1e-3;

/// \brief Largest translation component accepted, metres: 1000 km, beyond any sensor map
/// (a float coordinate there still resolves 6 cm).
constexpr double kMaxTranslation = 1e6;

/// \brief Largest angle accepted where a rotation is given as angles (g2o theta, roll pitch
/// yaw), radians: unwrapped headings of 150 000 turns still resolve 1e-10 rad; at 1e17 a double
/// no longer tells one turn from the next (its spacing there is 16 rad).
constexpr double kMaxAngle = 1e6;

/// \brief Throw std::invalid_argument "WHAT: REASON" unless `m` is a rigid transform: the upper
/// left 3x3 orthonormal within kRotationTolerance with determinant +1, the translation finite
/// and within kMaxTranslation, and (when `check_last_row`) the last row 0 0 0 1.
void checkRigidTransform(const Eigen::Matrix4d& m, const std::string& what,
                         bool check_last_row = true);

}  // namespace metricmap
