#pragma once
/// \file kitti_drift.h
/// \brief Drift as the KITTI odometry devkit computes it (evaluate_odometry.cpp): segments of
/// 100, 200, ..., 800 m of the reference path starting every 10th frame; per segment
/// E = (P_a^-1 P_b)^-1 (Q_a^-1 Q_b) with t_err = |trans(E)| / length, r_err = angle(E) / length;
/// averaged over all segments. The estimate is taken as given (the devkit aligns nothing).

#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

namespace metricmap {

/// \brief The devkit's constants.
struct KittiDriftConfig {
  std::vector<double> lengths{100, 200, 300, 400, 500, 600, 700, 800};  ///< metres
  std::size_t step = 10;  ///< frames between segment starts
};

/// \brief The segments of one length: count and average errors (0 when there are none).
struct KittiDriftLength {
  double length = 0.0;
  std::size_t segments = 0;
  double translation_percent = 0.0;  ///< 100 * mean t_err
  double rotation_deg_per_m = 0.0;   ///< mean r_err, degrees per metre
};

/// \brief The drift over all segments (0 when none fits: a run shorter than the shortest
/// length), and per length.
struct KittiDrift {
  double path_length = 0.0;  ///< metres along the reference
  std::size_t segments = 0;
  double translation_percent = 0.0;
  double rotation_deg_per_m = 0.0;
  std::vector<KittiDriftLength> lengths;
};

/// \brief The devkit's drift of `estimate` against `reference`, pose i with pose i.
///
/// As calcSequenceErrors: distances accumulate along the reference positions; the segment of
/// length L from frame a ends at the first frame b whose distance exceeds dist(a) + L (none:
/// no segment). Relative poses use general 4x4 inverses and r_err = acos((trace - 1) / 2) / L,
/// as the devkit; computed in double precision (the devkit uses float).
/// \throws std::invalid_argument when the counts differ, step is 0 or a length is not > 0
KittiDrift kittiDrift(const std::vector<Eigen::Isometry3d>& estimate,
                      const std::vector<Eigen::Isometry3d>& reference,
                      const KittiDriftConfig& config = {});

}  // namespace metricmap
