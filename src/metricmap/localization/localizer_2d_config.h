#pragma once
/// \file localizer_2d_config.h
/// \brief Parameters of the 2D localiser (Localizer2D) and their defaults, chosen on the SLAM
/// benchmark's logs localised in maps that `slam2d` made of them (docs/LOCALIZATION.md).

#include <cstddef>

namespace metricmap {

/// \brief Everything Localizer2D can be told.
struct Localizer2DConfig {
  // --- scans
  double min_range = 0.0;       ///< beams shorter than this are dropped (m, >= 0)
  double max_range = 30.0;      ///< longer beams are dropped (m, > min_range)
  double voxel_filter = 0.025;  ///< points kept for matching: one per square of this edge (m, > 0)

  // --- the map as matching sees it: occupied cells at this probability, free and unknown
  // cells at the lowest (Cartographer's convention for unexplored space); a scale-mode cell
  // of value v at v / 100 between them.
  double occupied_probability = 0.971;  ///< (0.5, 1)
  double free_probability = 0.1192;     ///< (0, 0.5)

  // --- global search (no pose yet, or lost): branch-and-bound over the whole map and headings
  int branch_and_bound_depth = 6;  ///< levels of the multi-resolution grids (1..16)
  /// The search runs on the map coarsened this many times (cells of 2 x 2 map cells: four
  /// times fewer positions, half the headings), exactly there; a correlative search over one
  /// coarse cell on the map itself follows (1..8; 1: the map itself).
  int global_coarsening = 2;
  std::size_t global_search_points = 200;  ///< points the search scores, at most (>= 10)
  /// The best pose is accepted when its refined score reaches this ...
  double global_min_score = 0.6;  ///< (0, 1)
  /// ... and its search score exceeds that of the best distinct pose by this much ([0, 1]).
  double global_min_margin = 0.05;
  /// ... and at most this share of its beams pass through an occupied cell of the map more than
  /// global_crossing_clearance before their end (a scan placed where it would see through
  /// walls is in another place, or another building) ([0, 1]).
  double global_max_crossing = 0.25;
  double global_crossing_clearance = 0.3;  ///< m (>= 0)
  /// Poses farther apart than this, or turned more than global_distinct_angle_deg, are
  /// distinct (a symmetric building's twin places).
  double global_distinct_distance = 1.0;    ///< m (> 0)
  double global_distinct_angle_deg = 20.0;  ///< deg (> 0)
  /// While not localised, a scan is searched once the odometry has moved this far or turned
  /// this much since the last search (the same view gives the same answer) ...
  double global_min_motion = 0.2;     ///< m (>= 0)
  double global_min_turn_deg = 10.0;  ///< deg (>= 0)
  /// ... or this many scans after it (without odometry: the only rule) (>= 1).
  std::size_t global_every_n_scans = 20;

  // --- an initial pose given by the user: searched in this window around it
  double initial_linear_window = 1.0;        ///< m (> 0)
  double initial_angular_window_deg = 20.0;  ///< deg (> 0)

  // --- tracking: each scan matched against the map from the motion prediction
  double track_linear_window = 0.1;            ///< correlative search half-width (m, >= 0)
  double track_angular_window_deg = 1.0;       ///< correlative search half-width (deg, >= 0)
  double track_angular_window_per_turn = 0.2;  ///< plus this share of the predicted turn
  double translation_weight = 1.0;             ///< Gauss-Newton prior on the search's translation
  double rotation_weight = 1.0;                ///< Gauss-Newton prior on the search's heading
  int refine_iterations = 10;                  ///< Gauss-Newton steps (1..1000)
  /// A tracked scan whose score falls below this is weak: its pose is kept for the next
  /// prediction but not reported ((0, 1)).
  double track_min_score = 0.55;
  /// After this many weak scans in a row the robot is lost: the global search takes over (>= 1).
  std::size_t lost_after_weak_scans = 5;
};

/// \brief \throws std::invalid_argument "NAME must be RULE, got VALUE" for the first value out of
/// its declared range (localizer2DParameterSchema), or max_range <= min_range.
void validateLocalizer2DConfig(const Localizer2DConfig& config);

}  // namespace metricmap
