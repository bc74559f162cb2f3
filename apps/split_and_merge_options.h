#pragma once
/// \file split_and_merge_options.h
/// \brief The Split & Merge options of `metricmap lines` (--distance-threshold ...
/// --bearing-sigma-deg) and the SplitAndMergeParams they give.

#include <cmath>
#include <string>

#include <CLI/CLI.hpp>

#include "metricmap/lines/split_and_merge_types.h"

namespace metricmap::cli {

struct SplitAndMergeOptions {
  // Defaults: the library's (SplitAndMergeParams), angles shown in degrees.
  double distance = SplitAndMergeParams{}.distance_threshold;
  double angle_deg = SplitAndMergeParams{}.angle_threshold * 180.0 / M_PI;
  double min_length = SplitAndMergeParams{}.min_length, max_gap = SplitAndMergeParams{}.max_gap;
  double chi2 = 0.0;  // 0: split on distance; > 0: the chi-square test with this threshold
  long long min_points = static_cast<long long>(SplitAndMergeParams{}.min_points);
  double range_sigma = SplitAndMergeParams{}.range_sigma;
  double bearing_sigma_deg = SplitAndMergeParams{}.bearing_sigma * 180.0 / M_PI;
  std::string purge = "before-merge";
};

/// \brief Adds the options.
void addSplitAndMergeOptions(CLI::App& app, SplitAndMergeOptions& o);

/// \brief Options that would change nothing in this run are refused:
/// --purge with nothing to purge or no merge step, the noise model without --chi2 or `json`.
void checkSplitAndMergeOptions(const CLI::App& app, const SplitAndMergeOptions& o, bool json);

/// \brief The parameters; degrees are converted only when given, so the defaults stay the
/// library's bit for bit.
SplitAndMergeParams splitAndMergeParams(const SplitAndMergeOptions& o);

}  // namespace metricmap::cli
