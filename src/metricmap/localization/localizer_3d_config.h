#pragma once
/// \file localizer_3d_config.h
/// \brief Parameters of the 3D localiser (localizer_3d.h).

#include "metricmap/slam3d/loop_verification.h"
#include "metricmap/slam3d/scan_context.h"

namespace metricmap {

struct Localizer3DConfig {
  // The scan.
  double min_range = 1.0;   ///< returns closer are dropped (the platform itself) (m, >= 0)
  double max_range = 80.0;  ///< returns farther are dropped (m, > min_range)
  double scan_voxel = 0.5;  ///< points kept for matching: the first of each cube of this edge (m)

  // The map as the scans are matched against it.
  double map_voxel = 1.0;         ///< voxel of the map's hash (m, > 0)
  int map_points_per_voxel = 20;  ///< points a voxel keeps (1..1000)

  // Places: where the global search looks for the scan.
  double place_spacing = 3.0;       ///< a grid of candidate places this far apart (m, > 0)
  double place_cell = 0.5;          ///< cell of the map's height image (m, > 0, <= place_spacing)
  double place_clearance = 2.0;     ///< a place is free of map points this high over its ground (m)
  int place_min_ground_points = 5;  ///< map points a place's ground needs (>= 1)
  /// Heights in both descriptors are clipped to clip_height + clip_slope × range above the
  /// ground: the sensor's upward field of view, so that the map does not show what a scan at
  /// that place cannot see (tops of tall buildings).
  double clip_height = 2.0;                         ///< m (> 0)
  double clip_slope = 0.2;                          ///< m per m (>= 0)
  ScanContextParams descriptor{20, 60, 40.0, 0.5};  ///< height_offset: ground's value

  // Ground of a scan (levelling for the descriptor and the global guess).
  double ground_threshold = 0.15;     ///< plane inlier distance (m, > 0)
  double ground_max_tilt_deg = 25.0;  ///< the ground's normal within this of the sensor's z (deg)

  // Global search (no pose, or lost).
  int global_candidates = 8;  ///< places with the nearest descriptors verified (>= 1)
  /// min_structure_overlap 0.8: at the right place 90 % of the structure lies on the map; a
  /// map of somewhere else reaches about 0.7.
  LoopVerificationParams verify{3.0, 0.6, 1.0, 0.4, 0.5, 0.8, 0.5, 8.0};
  /// The best verified pose's structure overlap must exceed the best distinct pose's by this.
  double global_min_margin = 0.1;           ///< [0, 1]
  double global_distinct_distance = 3.0;    ///< poses farther apart are distinct (m, > 0)
  double global_distinct_angle_deg = 30.0;  ///< or turned more than this (deg, > 0)

  // Tracking.
  double track_coarse_threshold = 1.5;  ///< first ICP stage's correspondence distance (m, > 0)
  double track_fine_threshold = 0.5;    ///< last stage's (m, > 0, <= coarse)
  double track_yaw_window_deg = 24.0;   ///< headings tried around the prediction (deg, >= 0)
  double track_yaw_step_deg = 6.0;      ///< their step (deg, > 0)
  int track_iterations = 30;            ///< Gauss-Newton steps per stage (1..1000)
  double overlap_distance = 0.5;        ///< a scan point overlaps within this of the map (m, > 0)
  double track_min_overlap = 0.5;       ///< scans overlapping less are weak ([0, 1])
  int lost_after_weak_scans = 3;        ///< weak scans in a row that lose the track (>= 1)
  /// A tracked pose may move at most this far from the prediction (m, > 0).
  double track_max_correction = 3.0;
};

/// \brief \throws std::invalid_argument naming the first bad field
void validateLocalizer3DConfig(const Localizer3DConfig& config);

}  // namespace metricmap
