#pragma once
/// \file occupancy_report.h
/// \brief The report of `metricmap occupancy`: counts, voxels, memory and seconds as JSON or a
/// one-row table.

#include <string>

#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "metricmap/occupancy/scan_casting.h"

namespace metricmap::cli {

/// \brief The casting totals with what the command adds.
struct OccupancyTotals : ScanCastTotals {
  double write_s = 0;
  double insert_cpu_s = -1;  ///< distributed: insert seconds summed over the ranks
};

/// \brief The report's text for --format json or table; `trinary` is reported with --out-map
/// (`with_map`).
std::string occupancyReport(const std::string& format, const LogOddsMap& map,
                            const OccupancyTotals& tot, bool with_map, const TrinaryMap& trinary);

}  // namespace metricmap::cli
