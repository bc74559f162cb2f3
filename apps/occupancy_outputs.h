#pragma once
/// \file occupancy_outputs.h
/// \brief The files `metricmap occupancy` writes, computed before the first is written and
/// staged: OctoMap .bt/.ot, the occupied voxel centres, the trinary map_server map and its
/// preview.

#include <utility>

#include "metricmap/io/output_set.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "occupancy_options.h"

namespace metricmap::cli {

/// \brief The trinary map of --out-map (`band`: zmin, zmax); empty without --out-map.
/// \throws CapacityError naming --out-map and --band when the map would not fit the budget
TrinaryMap occupancyTrinaryMap(const OccupancyOptions& o, const LogOddsMap& map,
                               const std::pair<double, double>& band);

/// \brief Stage and write --out, --out-ot, --out-cloud and --out-map (`trinary`, with
/// --map-preview).
void writeOccupancyOutputs(const OccupancyOptions& o, const LogOddsMap& map,
                           const TrinaryMap& trinary, OutputSet& outputs);

}  // namespace metricmap::cli
