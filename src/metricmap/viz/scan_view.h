#pragma once
/// \file scan_view.h
/// \brief What the SVG and PNG drawings of a scan share: the view transform and the colours.

#include <algorithm>
#include <array>
#include <cmath>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace metricmap::viz {

/// \brief Maps metres to drawing pixels (y up on screen); the sensor (origin) is always in view.
struct ScanView {
  double lo_x = 0, lo_y = 0, scale = 1, size = 800, margin = 40;
  double px(double x) const { return margin + (x - lo_x) * scale; }
  double py(double y) const { return size - margin - (y - lo_y) * scale; }

  static ScanView fit(const pcl::PointCloud<pcl::PointXYZ>& scan, double size) {
    ScanView v;
    v.size = size;
    double hi_x = 0, hi_y = 0;
    for (const auto& p : scan) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      v.lo_x = std::min<double>(v.lo_x, p.x);
      hi_x = std::max<double>(hi_x, p.x);
      v.lo_y = std::min<double>(v.lo_y, p.y);
      hi_y = std::max<double>(hi_y, p.y);
    }
    const double span = std::max({hi_x - v.lo_x, hi_y - v.lo_y, 1.0});
    v.scale = (size - 2 * v.margin) / span;
    return v;
  }
};

/// \brief Colour of segment k, RGB 0-255: golden-angle hues so neighbours differ clearly.
inline std::array<int, 3> segmentColour(std::size_t k) {
  const double h = std::fmod(static_cast<double>(k) * 137.508, 360.0) / 60.0;
  const double c = 0.75, x = c * (1 - std::fabs(std::fmod(h, 2.0) - 1)), m = 0.08;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0:
      r = c, g = x;
      break;
    case 1:
      r = x, g = c;
      break;
    case 2:
      g = c, b = x;
      break;
    case 3:
      g = x, b = c;
      break;
    case 4:
      r = x, b = c;
      break;
    default:
      r = c, b = x;
      break;
  }
  return {static_cast<int>((r + m) * 255), static_cast<int>((g + m) * 255),
          static_cast<int>((b + m) * 255)};
}

}  // namespace metricmap::viz
