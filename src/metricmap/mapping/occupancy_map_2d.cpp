#include "metricmap/mapping/occupancy_map_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "metricmap/common/format_number.h"
#include "metricmap/detail/fast_floor.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

std::uint64_t pack(std::int64_t i, std::int64_t j) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(static_cast<std::int32_t>(i)))
          << 32) |
         static_cast<std::uint32_t>(static_cast<std::int32_t>(j));
}

void unpack(std::uint64_t key, std::int64_t& i, std::int64_t& j) {
  i = static_cast<std::int32_t>(static_cast<std::uint32_t>(key >> 32));
  j = static_cast<std::int32_t>(static_cast<std::uint32_t>(key & 0xFFFFFFFFu));
}

}  // namespace

MapPlane parseMapPlane(const std::string& name) {
  if (name == "xz") return MapPlane::XZ;
  if (name == "xy") return MapPlane::XY;
  if (name == "yz") return MapPlane::YZ;
  throw std::invalid_argument("map plane must be xz, xy or yz, got '" + name + "'");
}

OccupancyMap2D::OccupancyMap2D(double resolution, MapPlane plane)
    : resolution_(resolution), plane_(plane) {
  if (!std::isfinite(resolution) || !(resolution > 0.0)) {
    throw std::invalid_argument("map resolution must be a finite number > 0");
  }
}

void OccupancyMap2D::add(const pcl::PointCloud<pcl::PointXYZ>& world_points) {
  const double inv = 1.0 / resolution_;
  const int a = plane_ == MapPlane::YZ ? 1 : 0;
  const int b = plane_ == MapPlane::XY ? 1 : 2;
  constexpr double kLimit = 2.0e9;  // cell indices stay within int32
  for (const pcl::PointXYZ& p : world_points) {
    const float* v = &p.x;
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) continue;
    const double u = v[a] * inv, w = v[b] * inv;
    if (std::fabs(u) > kLimit || std::fabs(w) > kLimit) {
      throw CapacityError("map resolution " + formatNumber(resolution_) +
                          " m too fine for a point at " + formatNumber(v[a]) + ", " +
                          formatNumber(v[b]) + " (cell index beyond 2e9)");
    }
    ++hits_[pack(floorToInt(u), floorToInt(w))];
  }
}

std::size_t OccupancyMap2D::occupied(std::uint32_t min_hits) const {
  std::size_t n = 0;
  for (const auto& [key, count] : hits_) n += count >= min_hits ? 1 : 0;
  return n;
}

MapImage OccupancyMap2D::image(std::uint64_t max_pixels) const {
  MapImage m;
  m.resolution = resolution_;
  if (hits_.empty()) return m;
  std::int64_t i0 = std::numeric_limits<std::int64_t>::max(), j0 = i0;
  std::int64_t i1 = std::numeric_limits<std::int64_t>::min(), j1 = i1;
  for (const auto& [key, count] : hits_) {
    std::int64_t i, j;
    unpack(key, i, j);
    i0 = std::min(i0, i);
    i1 = std::max(i1, i);
    j0 = std::min(j0, j);
    j1 = std::max(j1, j);
  }
  const std::uint64_t w = static_cast<std::uint64_t>(i1 - i0 + 1);
  const std::uint64_t h = static_cast<std::uint64_t>(j1 - j0 + 1);
  if (static_cast<double>(w) * static_cast<double>(h) > static_cast<double>(max_pixels)) {
    throw CapacityError("map image of " + std::to_string(w) + " x " + std::to_string(h) +
                        " cells at " + formatNumber(resolution_) + " m exceeds " +
                        std::to_string(max_pixels) + " pixels; use a coarser map resolution");
  }
  m.width = static_cast<int>(w);
  m.height = static_cast<int>(h);
  m.origin_x = static_cast<double>(i0) * resolution_;
  m.origin_y = static_cast<double>(j0) * resolution_;
  m.hits.assign(static_cast<std::size_t>(m.width) * m.height, 0);
  for (const auto& [key, count] : hits_) {
    std::int64_t i, j;
    unpack(key, i, j);
    m.hits[static_cast<std::size_t>(j1 - j) * m.width + static_cast<std::size_t>(i - i0)] = count;
  }
  return m;
}

MapServerImage mapServerImage(const MapImage& map, std::uint32_t min_hits) {
  if (map.width == 0) throw std::invalid_argument("the map is empty: no point was projected");
  MapServerImage out{map.width, map.height, map.resolution, map.origin_x, map.origin_y, {}, {}};
  out.pixels.resize(map.hits.size());
  for (std::size_t i = 0; i < map.hits.size(); ++i)
    out.pixels[i] = map.hits[i] >= min_hits && map.hits[i] > 0 ? kMapOccupied : kMapFree;
  return out;
}

std::vector<std::uint8_t> heatImage(const MapImage& map) {
  const std::uint32_t most = std::max<std::uint32_t>(
      1, map.hits.empty() ? 1 : *std::max_element(map.hits.begin(), map.hits.end()));
  std::vector<std::uint8_t> heat(map.hits.size() * 3, 0);
  const double scale = std::log1p(static_cast<double>(most));
  for (std::size_t i = 0; i < map.hits.size(); ++i) {
    if (map.hits[i] == 0) continue;
    const double t = std::log1p(static_cast<double>(map.hits[i])) / scale;  // 0..1
    heat[3 * i] = static_cast<std::uint8_t>(255 * std::min(1.0, 1.5 * t));
    heat[3 * i + 1] = static_cast<std::uint8_t>(255 * std::max(0.0, 1.5 * t - 0.5));
    heat[3 * i + 2] = static_cast<std::uint8_t>(255 * std::max(0.0, 0.6 - t));
  }
  return heat;
}

}  // namespace metricmap
