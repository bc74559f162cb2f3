#pragma once
/// \file scan_matcher_2d.h
/// \brief Matching a 2D scan (points in the sensor frame) against a probability grid: an
/// exhaustive correlative search in a small window (Olson's real-time correlative matching),
/// then Gauss-Newton on the interpolated grid (bilinear or bicubic) with a prior on the search's
/// result (the cost of Cartographer's Ceres scan matcher: Σ ((1 - M(T p_k)) / √N)² plus weighted
/// squared translation and rotation away from the prior).

#include <vector>

#include <Eigen/Core>

#include "metricmap/common/pose_2d.h"
#include "metricmap/slam/match_grid.h"

namespace metricmap {

/// \brief A pose found for a scan and its score: the mean probability of the cells its points
/// fall in (nearest cell), in [table.min(), table.max()].
struct ScanMatch2D {
  Pose2D pose;
  double score = 0.0;
};

/// \brief The angular step at which the farthest point moves by about one cell (Cartographer:
/// acos(1 - r² / (2 d²)) for resolution r and range d), at most 1 degree.
double angularSearchStep(double resolution, const std::vector<Eigen::Vector2f>& points);

/// \brief Mean nearest-cell probability of the points placed at `pose`.
double scoreAt(const MatchGrid& grid, const std::vector<Eigen::Vector2f>& points,
               const Pose2D& pose);

/// \brief Every pose initial + (dx, dy, dθ) with |dx|, |dy| <= linear_window on the grid's
/// cells and |dθ| <= angular_window in steps of angular_step; the best score wins (the
/// candidate nearest the initial pose among equals).
ScanMatch2D correlativeSearch(const MatchGrid& grid, const std::vector<Eigen::Vector2f>& points,
                              const Pose2D& initial, double linear_window, double angular_window,
                              double angular_step);

/// \brief A prior on the translation along the directions the scan hardly constrains: those
/// where the data term's information (the eigenvalues of its translation block, per m²) is
/// below `min_information`. In a corridor, the scan's points barely change their cells'
/// probabilities as the scan slides along it, while the edge of what the grid has seen pulls
/// it back: this prior holds the scan where `target` (the odometry's prediction) puts it.
struct WeakDirectionPrior {
  Eigen::Vector2d target = Eigen::Vector2d::Zero();
  double weight = 0.0;           ///< like translation_weight, along the weak directions only
  double min_information = 0.0;  ///< per m²
};

/// \brief Gauss-Newton from `initial` (at most `iterations` steps, stopping when a step moves
/// less than 1e-6 m and rad), with the prior `prior` weighted by translation_weight and
/// rotation_weight (and `weak`, when given), on the bicubic surface (`cubic`) or the bilinear
/// one. The score is the nearest-cell score at the result.
ScanMatch2D refinePose(const MatchGrid& grid, const std::vector<Eigen::Vector2f>& points,
                       const Pose2D& initial, const Pose2D& prior, double translation_weight,
                       double rotation_weight, int iterations, bool cubic = false,
                       const WeakDirectionPrior* weak = nullptr);

}  // namespace metricmap
