#pragma once
/// \file relative_error.h
/// \brief Relative pose error per frame, evo's `evo_rpe` at its default (delta = 1 frame):
/// E_i = (Q_i^-1 Q_{i+1})^-1 (P_i^-1 P_{i+1}) for the reference Q and the estimate P, its
/// translation's length (metres) and its rotation angle (degrees).

#include <vector>

#include <Eigen/Geometry>

#include "metricmap/evaluation/error_statistics.h"

namespace metricmap {

/// \brief Per-frame errors (entry i: from pose i to pose i + 1) and their statistics.
struct RelativeError {
  std::vector<double> translation;   ///< |trans(E_i)|, metres
  std::vector<double> rotation_deg;  ///< angle(E_i), degrees
  ErrorStatistics translation_stats;
  ErrorStatistics rotation_stats;
};

/// \brief The per-frame RPE of `estimate` against `reference`, pose i with pose i.
/// \throws std::invalid_argument when the counts differ
RelativeError relativeError(const std::vector<Eigen::Isometry3d>& estimate,
                            const std::vector<Eigen::Isometry3d>& reference);

}  // namespace metricmap
