#pragma once
/// \file absolute_error.h
/// \brief Absolute trajectory error (ATE), evo's APE: per pose, the distance between estimated
/// and reference positions ("translation part") and the angle of Q_i^-1 P_i (degrees).

#include <vector>

#include <Eigen/Geometry>

#include "metricmap/evaluation/error_statistics.h"

namespace metricmap {

/// \brief Per-pose errors and their statistics.
struct AbsoluteError {
  std::vector<double> translation;   ///< |p_i - q_i|, metres
  std::vector<double> rotation_deg;  ///< angle(Q_i^-1 P_i), degrees
  ErrorStatistics translation_stats;
  ErrorStatistics rotation_stats;
};

/// \brief The ATE of `estimate` (already aligned, see alignment.h) against `reference`, pose i
/// with pose i. \throws std::invalid_argument when the counts differ
AbsoluteError absoluteError(const std::vector<Eigen::Isometry3d>& estimate,
                            const std::vector<Eigen::Isometry3d>& reference);

}  // namespace metricmap
