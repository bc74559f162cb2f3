#pragma once
/// \file map_report.h
/// \brief The report of `metricmap map`: the source, the poses, the hit map and the 2D occupancy
/// grid, as JSON or two summary lines.

#include <chrono>
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "metricmap/mapping/occupancy_map_2d.h"

namespace metricmap::cli {

/// \brief What the report states.
struct MapReportFigures {
  std::string source, poses;  ///< the source's path; "reference" or "odometry"
  std::size_t frames = 0;
  double map_resolution = 0.0;
  std::size_t occupied_cells = 0;
  nlohmann::json grid;           ///< writeOccupancy2D's summary; null without the grid
  double grid_resolution = 0.0;  ///< --occupancy-2d-resolution
};

/// \brief The report's text for --format `format` (json or table); `t_start` the command's
/// start.
std::string mapReport(const std::string& format, const MapImage& image,
                      const MapReportFigures& figures,
                      std::chrono::steady_clock::time_point t_start);

}  // namespace metricmap::cli
