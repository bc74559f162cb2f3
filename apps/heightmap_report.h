#pragma once
/// \file heightmap_report.h
/// \brief The report of `metricmap heightmap`: JSON or a table.

#include <string>
#include <vector>

#include "metricmap/io/output_set.h"
#include "metricmap/mapping/height_map_builder.h"

namespace metricmap {
class HeightMap;
}

namespace metricmap::cli {

/// \brief Print the map's figures (`format` json, else a table of that style), then commit
/// `outputs` (emit's rule).
void emitHeightMapReport(const HeightMap& map, const std::vector<HeightMapFloor>& floors,
                         double seconds, const std::string& format, OutputSet& outputs);

}  // namespace metricmap::cli
