#pragma once
/// \file svg_drawing.h
/// \brief SVG drawings of a scan and its segments (points, segments in distinct colours,
/// endpoints marked, a 1 m scale bar, the sensor at the origin).

#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/lines/line_segment.h"

namespace metricmap::cli {

std::string drawScanSvg(const pcl::PointCloud<pcl::PointXYZ>& scan,
                        const std::vector<LineSegment>& segments, const std::string& title);

}  // namespace metricmap::cli
