#include "metricmap/occupancy/occupancy_export.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/map_server.h"

namespace metricmap {

TrinaryMap projectBand(const LogOddsMap& map, double z_min, double z_max) {
  if (!std::isfinite(z_min) || !std::isfinite(z_max) || z_min > z_max) {
    std::ostringstream msg;
    msg << "height band must be finite with zmin <= zmax, got " << z_min << "," << z_max;
    throw std::invalid_argument(msg.str());
  }
  const double res = map.resolution();
  auto inBand = [&](const VoxelKey& k) {
    const double zc = (static_cast<double>(k.z) + 0.5) * res;
    return zc >= z_min && zc <= z_max;
  };
  constexpr auto big = std::numeric_limits<std::int64_t>::max();
  std::int64_t x0 = big, y0 = big, x1 = -big, y1 = -big;
  map.forEachKnown([&](const VoxelKey& k, float) {
    if (!inBand(k)) return;
    x0 = std::min(x0, k.x);
    y0 = std::min(y0, k.y);
    x1 = std::max(x1, k.x);
    y1 = std::max(y1, k.y);
  });
  if (x0 > x1) {
    std::ostringstream msg;
    msg << "no observed voxel has its centre in the height band " << z_min << ".." << z_max;
    throw std::invalid_argument(msg.str());
  }
  // the image spans the band's voxels: two far-apart voxels (a few dozen bytes of .bt) ask for
  // 65536 x 65536 cells; the cells, their copy for the writers and a preview, within the budget
  const std::uint64_t w = static_cast<std::uint64_t>(x1 - x0) + 1;
  const std::uint64_t h = static_cast<std::uint64_t>(y1 - y0) + 1;
  {
    std::ostringstream what;
    what << "the trinary map of the band " << z_min << ".." << z_max << " (" << w << " x " << h
         << " cells of " << res << " m)";
    if (w > static_cast<std::uint64_t>(std::numeric_limits<int>::max()) ||
        h > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      throw CapacityError(what.str() + " is wider than an image can be");
    checkMemory(w * h, 4, what.str());
  }
  TrinaryMap m;
  m.width = static_cast<int>(w);
  m.height = static_cast<int>(h);
  m.resolution = res;
  m.origin_x = static_cast<double>(x0) * res;
  m.origin_y = static_cast<double>(y0) * res;
  m.cells.assign(static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height),
                 kMapUnknown);
  map.forEachKnown([&](const VoxelKey& k, float l) {
    if (!inBand(k)) return;
    std::uint8_t& c =
        m.cells[static_cast<std::size_t>(y1 - k.y) * static_cast<std::size_t>(m.width) +
                static_cast<std::size_t>(k.x - x0)];
    if (map.isOccupied(l))
      c = kMapOccupied;
    else if (c == kMapUnknown)
      c = kMapFree;
  });
  for (std::uint8_t c : m.cells) {
    m.occupied += c == kMapOccupied ? 1 : 0;
    m.free += c == kMapFree ? 1 : 0;
  }
  return m;
}

MapServerImage mapServerImage(const TrinaryMap& map) {
  if (map.width == 0) throw std::invalid_argument("the trinary map is empty");
  return {map.width,    map.height, map.resolution,        map.origin_x,
          map.origin_y, map.cells,  MapServerMode::Trinary};
}

std::vector<Eigen::Vector3d> voxelCenters(const LogOddsMap& map, bool occupied) {
  std::vector<Eigen::Vector3d> out;
  map.forEachKnown([&](const VoxelKey& k, float l) {
    if (map.isOccupied(l) == occupied) out.push_back(map.centerOf(k));
  });
  return out;
}

pcl::PointCloud<pcl::PointXYZ> occupiedCenters(const LogOddsMap& map) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  map.forEachKnown([&](const VoxelKey& k, float l) {
    if (!map.isOccupied(l)) return;
    const Eigen::Vector3d c = map.centerOf(k);
    cloud.push_back(pcl::PointXYZ(static_cast<float>(c.x()), static_cast<float>(c.y()),
                                  static_cast<float>(c.z())));
  });
  return cloud;
}

}  // namespace metricmap
