#pragma once
/// \file stats_json.h
/// \brief nlohmann::json conversions of the statistics structs.

#include <nlohmann/json.hpp>

#include "metricmap/grid/grid_types.h"
#include "metricmap/io/load_report.h"
#include "metricmap/octree/octree_types.h"

namespace metricmap {

void to_json(nlohmann::json& j, const GridStatistics& s);
void to_json(nlohmann::json& j, const OctreeStatistics& s);

}  // namespace metricmap
