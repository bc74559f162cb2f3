#include "metricmap/localization/point_map_3d.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/occupancy/octomap_io.h"

namespace metricmap {
namespace {

std::string lowerExtension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

/// The points' box; throws naming the first point beyond kMaxMapCoordinate.
Eigen::AlignedBox3d boundsOf(const std::vector<Eigen::Vector3f>& points) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3f& p : points) {
    if (p.cast<double>().cwiseAbs().maxCoeff() > kMaxMapCoordinate)
      throw std::invalid_argument("a map point lies beyond " +
                                  std::to_string(static_cast<long>(kMaxMapCoordinate)) +
                                  " m of the origin");
    box.extend(p.cast<double>());
  }
  return box;
}

}  // namespace

bool isPointMap3DPath(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".pcd" || ext == ".ply" || ext == ".bt" || ext == ".ot";
}

PointMap3D pointMap3D(const std::vector<Eigen::Vector3f>& points) {
  PointMap3D map;
  map.points.reserve(points.size());
  for (const Eigen::Vector3f& p : points)
    if (p.allFinite()) map.points.push_back(p);
  if (map.points.empty()) throw std::invalid_argument("the map has no finite point");
  map.bounds = boundsOf(map.points);
  map.format = "points";
  return map;
}

PointMap3D loadPointMap3D(const std::string& path) {
  const std::string ext = lowerExtension(path);
  std::vector<Eigen::Vector3f> points;
  PointMap3D map;
  if (ext == ".pcd" || ext == ".ply") {
    pcl::PointCloud<pcl::PointXYZ> cloud;
    loadCloud(path, cloud);  // throws InputError for no finite point
    checkMemory(cloud.size(), sizeof(Eigen::Vector3f), path + ": the map's points");
    points.reserve(cloud.size());
    for (const pcl::PointXYZ& p : cloud) points.emplace_back(p.x, p.y, p.z);
    map.format = ext.substr(1);
  } else if (ext == ".bt" || ext == ".ot") {
    OctomapUse use;
    use.bytes_per_occupied_voxel = sizeof(Eigen::Vector3f);
    use.purpose = "kept as map points";
    const LogOddsMap grid = readOctomap(path, LogOddsParams(), use);
    grid.forEachKnown([&](const VoxelKey& key, float log_odds) {
      if (grid.isOccupied(log_odds)) points.push_back(grid.centerOf(key).cast<float>());
    });
    if (points.empty()) throw InputError(path + ": the OctoMap has no occupied voxel");
    map.resolution = grid.resolution();
    map.format = "octomap";
  } else {
    throw InputError(path + ": a 3D map is a .pcd, .ply, .bt or .ot file");
  }
  try {
    map.bounds = boundsOf(points);
  } catch (const std::invalid_argument& e) {
    throw InputError(path + ": " + e.what());
  }
  map.points = std::move(points);
  return map;
}

}  // namespace metricmap
