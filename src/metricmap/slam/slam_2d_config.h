#pragma once
/// \file slam_2d_config.h
/// \brief Parameters of the 2D laser SLAM (Slam2D) and their defaults. Defaults follow
/// Cartographer's 2D configuration where it has one (submap size, sensor model, motion filter,
/// scan-matcher weights, loop-closure window and score), chosen for the SLAM benchmark's logs.

#include <cstddef>

#include "metricmap/occupancy/log_odds_params.h"

namespace metricmap {

/// \brief Everything Slam2D can be told.
struct Slam2DConfig {
  // --- scans
  double min_range = 0.0;   ///< beams shorter than this are dropped (m, >= 0)
  double max_range = 30.0;  ///< longer beams are dropped: no return, or too far to place (m)
  /// Points kept for matching: one per square of this edge (m, > 0; Cartographer's voxel filter).
  double voxel_filter = 0.025;

  // --- submaps (2D log-odds grids, OctoMap's sensor model)
  double resolution = 0.05;           ///< cell edge of submaps (m, > 0)
  std::size_t scans_per_submap = 90;  ///< scans a submap receives before the next one starts (>= 1)
  double prob_hit = 0.7;              ///< submap sensor model (OctoMap's hit/miss)
  double prob_miss = 0.4;

  // --- motion filter: a scan becomes a node (inserted, in the graph) once the robot has moved
  double node_min_distance = 0.2;   ///< m since the last node (>= 0)
  double node_min_angle_deg = 1.0;  ///< deg since the last node (>= 0)
  double node_max_time = 5.0;       ///< s since the last node (> 0)

  // --- local matching (scan to the active submap)
  double local_linear_window = 0.1;       ///< correlative search half-width (m, >= 0)
  double local_angular_window_deg = 1.0;  ///< correlative search half-width (deg, >= 0)
  /// ... plus this share of the turn the prediction makes since the last scan ([0, 10]; 0.2:
  /// a 20° turn searches ±5°): odometry's heading error grows with the turn.
  double local_angular_window_per_turn = 0.2;
  /// Weak directions: where the scan's match scores less than `weak_direction_min_gain` (mean
  /// probability) above the prediction's translation, the Gauss-Newton step is repeated with a
  /// prior of `weak_direction_weight` toward the prediction along the translation directions
  /// whose information (eigenvalues of the data term, times resolution²: the mean square
  /// change of a point's probability as the scan moves one cell) is below
  /// `weak_direction_information`. Only a fresh odometry reading is held so. In a corridor the
  /// scan otherwise slides back toward where the submap has seen the walls (the Intel log's top
  /// corridor: 3.6 of 4.5 m lost in 34 nodes), while odometry that is plainly wrong (FR079: the
  /// wheels turn, the robot does not) is still overruled. weight 0 disables it.
  double weak_direction_min_gain = 0.05;     ///< [0, 1]
  double weak_direction_information = 0.05;  ///< [0, 1e6]
  double weak_direction_weight = 10.0;       ///< [0, 1e6]
  double translation_weight = 1.0;           ///< Gauss-Newton prior on the search's translation
  double rotation_weight = 1.0;              ///< Gauss-Newton prior on the search's heading
  int refine_iterations = 10;                ///< Gauss-Newton steps (>= 1)
  /// Gauss-Newton on the bicubic surface (Cartographer's) instead of the bilinear one. Off by
  /// default: over ten runs of the Intel log it stays within the bilinear surface's spread, and
  /// with Cartographer's prior weights it bends FR079's corridor (docs/SLAM.md).
  bool bicubic = false;

  // --- loop closure (branch-and-bound against finished submaps)
  double loop_linear_window = 2.0;        ///< search half-width (m, > 0)
  double loop_angular_window_deg = 10.0;  ///< search half-width (deg, > 0)
  double loop_min_score = 0.6;            ///< mean hit probability a match must reach (0, 1)
  double loop_max_distance = 8.0;         ///< submaps whose centre is farther are not searched (m)
  /// Submaps finished this many nodes before the searched one are also searched in the wide
  /// window below, once in `wide_every_n_nodes` nodes, without the overlap condition: the
  /// closing of a large loop, where the drift exceeds the near window.
  std::size_t wide_min_node_gap = 300;
  std::size_t wide_every_n_nodes = 15;  ///< (>= 1)
  /// ... and only when no loop was closed in this many nodes (0: always).
  std::size_t wide_idle_nodes = 30;
  double wide_linear_window = 6.0;        ///< m (> 0)
  double wide_angular_window_deg = 25.0;  ///< deg (> 0)
  std::size_t loop_every_n_nodes = 5;     ///< nodes searched: one in this many (>= 1)
  /// Submaps that received a node fewer than this many nodes ago are not searched (0: all
  /// finished submaps are; on the Intel log, skipping the recent ones cost accuracy).
  std::size_t loop_min_node_gap = 0;
  /// A submap is searched only when this share of the node's points, at its estimate, falls on
  /// cells the submap has observed ([0, 1]).
  double loop_min_overlap = 0.5;
  /// After each optimisation, loop edges whose chi² exceeds this are removed as false matches
  /// (> 0; chi² of 3 degrees of freedom: 11.3 is its 99 % point).
  double loop_max_chi2 = 100.0;
  /// The near search takes the nearest this many submaps that pass the overlap test (>= 1).
  std::size_t loop_max_submaps = 2;
  std::size_t loop_search_points = 90;  ///< points the search scores, at most (>= 10)
  int branch_and_bound_depth = 7;       ///< levels of the multi-resolution grids (1..16)

  // --- pose graph
  double edge_translation_sigma = 0.005;     ///< m, of the edges between consecutive nodes (> 0)
  double edge_rotation_sigma_deg = 0.25;     ///< deg (> 0)
  double loop_translation_sigma = 0.05;      ///< m, of loop edges (> 0)
  double loop_rotation_sigma_deg = 0.5;      ///< deg (> 0)
  std::size_t optimize_every_n_nodes = 180;  ///< optimise when loops were added (>= 1)
  int optimize_iterations = 10;              ///< Levenberg-Marquardt steps while running (>= 1)
  int final_iterations = 100;                ///< at the end (>= 1)

  // --- final map
  /// The map rebuilt from every node at its optimised pose (OctoMap's sensor model by default).
  LogOddsParams map{0.05, 0.7, 0.4, 0.1192, 0.971, 0.5, 30.0};
};

/// \brief \throws std::invalid_argument naming the first value out of its range.
void validateSlam2DConfig(const Slam2DConfig& config);

}  // namespace metricmap
