#pragma once
/// \file odometry_report.h
/// \brief The report of `metricmap odometry`: per-frame poses and registration figures, the
/// settings used and where they came from, the difference from the reference, as JSON or a table
/// with summary lines.

#include <chrono>
#include <string>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/sequence/odometry_run.h"
#include "sequence_options.h"

namespace metricmap::cli {

/// \brief The report's text for --format `format`; `profile` and `ranges` as given (they say
/// where the range window and voxel came from), `t_start` the command's start.
std::string odometryReport(const std::string& format, const std::string& profile,
                           const RangeOptions& ranges, const SourceInfo& info, const OdometryRun& r,
                           std::chrono::steady_clock::time_point t_start);

}  // namespace metricmap::cli
