#pragma once
/// \file point_map_3d.h
/// \brief A 3D map to localise in, as points in the map's frame: a point-cloud map (.pcd, .ply:
/// its points) or an OctoMap (.bt, .ot: the centres of its occupied voxels).

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace metricmap {

/// \brief The loaded map.
struct PointMap3D {
  std::vector<Eigen::Vector3f> points;  ///< map frame, all finite
  Eigen::AlignedBox3d bounds;           ///< of the points
  double resolution = 0.0;              ///< OctoMap voxel edge (m); 0 for a point cloud
  std::string format;                   ///< "pcd", "ply", "octomap"
};

/// \brief Largest |coordinate| of a map point (m): farther means a file in other units or a
/// corrupt one.
constexpr double kMaxMapCoordinate = 1e6;

/// \brief True for a name ending in .pcd, .ply, .bt or .ot (any case).
bool isPointMap3DPath(const std::string& path);

/// \brief Load a 3D map chosen by extension (.pcd, .ply, .bt, .ot; any case). Sizes are checked
/// against the memory budget before anything is allocated (the cloud readers' header checks;
/// the OctoMap expansion counted first).
/// \throws InputError naming the file for a missing, malformed or truncated one, one without a
/// finite point (NaN points are dropped) or an occupied voxel, or a point beyond
/// kMaxMapCoordinate; CapacityError when it does not fit the budget
PointMap3D loadPointMap3D(const std::string& path);

/// \brief A map from points already in memory (NaN points dropped).
/// \throws std::invalid_argument when no finite point is left or one lies beyond
/// kMaxMapCoordinate
PointMap3D pointMap3D(const std::vector<Eigen::Vector3f>& points);

}  // namespace metricmap
