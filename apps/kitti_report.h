#pragma once
/// \file kitti_report.h
/// \brief The report of `metricmap kitti`: the JSON (counts, seconds, the map, the registration
/// experiment's per-frame errors, the odometry, the 3D occupancy map) or the one-row table.

#include <string>

#include "kitti_options.h"

namespace metricmap {
struct MapImage;
}

namespace metricmap::cli {

/// \brief What the report says beyond the run itself.
struct KittiReportFigures {
  std::size_t global_points = 0;
  double write_s = 0.0, total_s = 0.0;
};

/// \brief The report's text in --format `o.format` (json, or the table's styles).
std::string kittiReport(const KittiOptions& o, const KittiMappingOptions& m,
                        const KittiMappingRun& run, const MapImage& image,
                        const KittiReportFigures& figures);

}  // namespace metricmap::cli
