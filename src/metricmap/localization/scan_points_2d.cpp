#include "metricmap/localization/scan_points_2d.h"

#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace metricmap {

std::vector<Eigen::Vector2f> scanPoints2D(const LaserScan& scan, const Pose2D& s, double min_range,
                                          double max_range, double voxel) {
  const double c = std::cos(s.theta), sn = std::sin(s.theta);
  std::vector<Eigen::Vector2f> kept;
  std::unordered_set<std::int64_t> seen;
  const std::size_t n = std::min(scan.angles.size(), scan.ranges.size());
  seen.reserve(n * 2);
  for (std::size_t k = 0; k < n; ++k) {
    const double r = scan.ranges[k], a = scan.angles[k];
    if (!(r >= min_range && r <= max_range) || !std::isfinite(a)) continue;
    const double px = r * std::cos(a), py = r * std::sin(a);
    const Eigen::Vector2f p(static_cast<float>(s.x + c * px - sn * py),
                            static_cast<float>(s.y + sn * px + c * py));
    const auto i = static_cast<std::int64_t>(std::floor(p.x() / voxel));
    const auto j = static_cast<std::int64_t>(std::floor(p.y() / voxel));
    if (seen.insert(i * 73856093 ^ j * 19349663).second) kept.push_back(p);
  }
  return kept;
}

std::vector<Eigen::Vector2f> spreadSubset(const std::vector<Eigen::Vector2f>& points,
                                          std::size_t count) {
  if (points.size() <= count || count == 0) return points;
  std::vector<Eigen::Vector2f> out;
  out.reserve(count);
  for (std::size_t k = 0; k < count; ++k) out.push_back(points[k * points.size() / count]);
  return out;
}

}  // namespace metricmap
