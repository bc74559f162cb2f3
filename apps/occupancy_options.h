#pragma once
/// \file occupancy_options.h
/// \brief The options of `metricmap occupancy` and their checks before any work.

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "metricmap/occupancy/log_odds_params.h"
#include "metricmap/occupancy/occupancy_inputs.h"
#include "metricmap/occupancy/octomap_io.h"

namespace metricmap::cli {

struct OccupancyOptions {
  std::vector<std::string> inputs;
  std::string sequence = "00", frames, world = "velodyne";
  std::string out_bt, out_ot, out_cloud, out_map, map_preview, band, format = "table";
  std::string pcd_format = "binary", topic, reference;
  double resolution = std::numeric_limits<double>::quiet_NaN();
  double max_range = std::numeric_limits<double>::quiet_NaN();
  unsigned threads = 1;
  bool threads_given = false;
  bool resolution_given = false, max_range_given = false, distributed = false;
  bool sequence_given = false, world_given = false, pcd_format_given = false;
};

/// \brief What the checks leave: --band, and the map's parameters (the defaults for a map read
/// from a file).
struct OccupancyPlan {
  std::pair<double, double> band{0, 0};
  LogOddsParams params;
};

/// \brief Usage checks (exit 2), before anything is read: options that do not apply to the
/// inputs given, --band and --world with --out-map, inputs or outputs naming one file, the
/// outputs' extensions, --map-preview without --out-map, --resolution and --max-range for scans.
/// \throws UsageError, CLI::ValidationError
OccupancyPlan checkOccupancyOptions(const OccupancyOptions& o, OccupancyInputKind kind);

/// \brief What the exports of a .bt/.ot input build per expanded voxel (octomapExportUse).
OctomapUse occupancyExportUse(const OccupancyOptions& o);

}  // namespace metricmap::cli
