#pragma once
/// \file scan_png.h
/// \brief PNG drawing of a scan and its segments through VTK (vtkImageCanvasSource2D +
/// vtkPNGWriter): points, segments in distinct colours, endpoints, sensor, a 1 m scale bar.

#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/lines/line_segment.h"

namespace metricmap::viz {

/// \brief Write the drawing to `path` (through a temporary file and a rename).
/// \throws std::runtime_error naming the file on failure
void writeScanPng(const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& scan,
                  const std::vector<LineSegment>& segments);

}  // namespace metricmap::viz
