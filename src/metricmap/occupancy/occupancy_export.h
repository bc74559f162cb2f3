#pragma once
/// \file occupancy_export.h
/// \brief What a LogOddsMap gives to other tools: a trinary 2D map_server map from a height
/// band, and the occupied voxel centres as a cloud.

#include <cstdint>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/common/map_server_image.h"
#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {

/// \brief A top-down (x right, y up) trinary image; row 0 holds the largest y. origin is the
/// world (x, y) of the lower-left corner of the lower-left pixel.
struct TrinaryMap {
  int width = 0, height = 0;
  double resolution = 0.0, origin_x = 0.0, origin_y = 0.0;
  std::vector<std::uint8_t> cells;  ///< kMapOccupied | kMapFree | kMapUnknown, row-major
  std::size_t occupied = 0, free = 0;
};

/// \brief Project the voxels whose centre z lies in [z_min, z_max] onto the xy plane: a column
/// is occupied if any of its voxels in the band is occupied, free if it has observed voxels in
/// the band and all are free, unknown otherwise. The image spans the known voxels' x/y bounds.
/// \throws std::invalid_argument for a band that is not finite with z_min <= z_max, or when no
/// known voxel lies in the band
TrinaryMap projectBand(const LogOddsMap& map, double z_min, double z_max);

/// \brief The map as map_server reads it (io/map_server.h writes it), `mode: trinary`.
/// \throws std::invalid_argument for an empty map
MapServerImage mapServerImage(const TrinaryMap& map);

/// \brief The centres of the occupied voxels (`occupied` true) or of the free ones.
std::vector<Eigen::Vector3d> voxelCenters(const LogOddsMap& map, bool occupied);

/// \brief The centres of the occupied voxels.
pcl::PointCloud<pcl::PointXYZ> occupiedCenters(const LogOddsMap& map);

}  // namespace metricmap
