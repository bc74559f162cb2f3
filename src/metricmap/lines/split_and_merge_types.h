#pragma once
/// \file split_and_merge_types.h
/// \brief Parameters and per-step trace of metricmap::SplitAndMerge (no PCL needed).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "metricmap/lines/line_segment.h"

namespace metricmap {

/// \brief When purge runs.
enum class PurgeOrder {
  /// After split, before merge (default): once short pieces such as chair legs are gone, merge
  /// can join the wall pieces on either side of them.
  BeforeMerge,
  /// After merge: only the final segments are judged.
  AfterMerge
};

/// \brief SplitAndMerge parameters. Distances in metres, angles in radians. The defaults are
/// `metricmap lines`' defaults.
struct SplitAndMergeParams {
  double distance_threshold = 0.05;  ///< d_th: split where the farthest point is further (> 0)
  /// a_th: merge neighbours whose chords (first to last point) differ less (0: off); 5 degrees
  double angle_threshold = 5.0 * 3.14159265358979323846 / 180.0;
  std::size_t min_points = 5;  ///< purge segments with fewer points (0: off)
  double min_length = 0.1;     ///< purge segments shorter than this (0: off)
  double max_gap = 0.0;        ///< split where consecutive valid points are further apart (0: off)
  PurgeOrder purge_order = PurgeOrder::BeforeMerge;
  /// Split on the chi-square test d^2 / var(d) > chi2_threshold instead of d > d_th, with the
  /// point covariance from range_sigma and bearing_sigma (sensor at the origin).
  bool chi2_split = false;
  double chi2_threshold = 6.63;  ///< 1 degree of freedom, 99 %
  double range_sigma = 0.01;     ///< metres, for the covariances of the fits and the chi2 test
  double bearing_sigma = 0.1 * 3.14159265358979323846 / 180.0;  ///< radians (0.1 degree)
};

/// \brief Called after every split, merge and purge with the current segments (for drawings
/// of the process). `what` is "split", "merge", "purge" or "gap".
using SplitAndMergeStep =
    std::function<void(const std::string& what, const std::vector<LineSegment>& segments)>;

/// \throws std::invalid_argument naming the bad value
void validateSplitAndMergeParams(const SplitAndMergeParams& params);

}  // namespace metricmap
