#include "metricmap/occupancy/occupancy_export.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "metricmap/io/array_writers.h"
#include "metricmap/io/cloud_writer.h"

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
  TrinaryMap m;
  m.width = static_cast<int>(x1 - x0 + 1);
  m.height = static_cast<int>(y1 - y0 + 1);
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

void writeTrinaryMapServer(const TrinaryMap& map, const std::string& pgm_path,
                           const std::string& preview_png) {
  const std::size_t slash = pgm_path.find_last_of('/');
  const std::string image = slash == std::string::npos ? pgm_path : pgm_path.substr(slash + 1);
  const std::string stem = pgm_path.substr(0, pgm_path.find_last_of('.'));
  writeTrinaryMapServer(map, pgm_path, stem + ".yaml", preview_png, image);
}

void writeTrinaryMapServer(const TrinaryMap& map, const std::string& pgm_path,
                           const std::string& yaml_path, const std::string& preview_png,
                           const std::string& image) {
  if (map.width == 0) throw std::invalid_argument("the trinary map is empty");
  YAML::Emitter yaml;
  yaml.SetDoublePrecision(10);
  yaml << YAML::BeginMap << YAML::Key << "image" << YAML::Value << image << YAML::Key << "mode"
       << YAML::Value << "trinary" << YAML::Key << "resolution" << YAML::Value << map.resolution
       << YAML::Key << "origin" << YAML::Value << YAML::Flow << YAML::BeginSeq << map.origin_x
       << map.origin_y << 0.0 << YAML::EndSeq << YAML::Key << "negate" << YAML::Value << 0
       << YAML::Key << "occupied_thresh" << YAML::Value << 0.65 << YAML::Key << "free_thresh"
       << YAML::Value << 0.196 << YAML::EndMap;
  writePgm(pgm_path, map.width, map.height, map.cells);
  writeTextAtomic(yaml_path, std::string(yaml.c_str()) + "\n");
  if (!preview_png.empty()) writePng(preview_png, map.width, map.height, 1, map.cells);
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
