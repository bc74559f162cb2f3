#pragma once
/// \file grid_report.h
/// \brief The report of `metricmap grid`: JSON or a table.

#include <cstdint>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/grid/grid_types.h"
#include "metricmap/io/output_set.h"

namespace metricmap::cli {

/// \brief What a build gives the outputs, from one process or from the ranks.
struct GridOutcome {
  std::uint64_t input_points = 0;
  GridStatistics stats;
  std::vector<GridCell> cells;
  pcl::PointCloud<pcl::PointXYZ> means;
  double load_s = 0.0, grid_s = 0.0;
};

/// \brief Print the figures of the grid of `files` (`format` json, else a table of that style),
/// then commit `outputs` (emit's rule).
void emitGridReport(const std::vector<std::string>& files, float cell_size,
                    const std::string& origin, const GridOutcome& g, const std::string& format,
                    OutputSet& outputs);

}  // namespace metricmap::cli
