#pragma once
/// \file occupancy_export.h
/// \brief What a LogOddsMap gives to other tools: a trinary 2D map_server map from a height
/// band, and the occupied voxel centres as a cloud.

#include <cstdint>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {

/// \brief map_server's trinary values.
constexpr std::uint8_t kMapOccupied = 0, kMapFree = 254, kMapUnknown = 205;

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

/// \brief Write the PGM (P5) and the YAML beside it (same stem): image, mode trinary,
/// resolution, origin [x, y, 0], negate 0, occupied_thresh 0.65, free_thresh 0.196; and a PNG
/// preview when `preview_png` is not empty. Each file through a temporary name and a rename.
void writeTrinaryMapServer(const TrinaryMap& map, const std::string& pgm_path,
                           const std::string& preview_png = "");

/// \brief The same with every path given (e.g. OutputSet temporaries): the PGM, the YAML, the
/// preview (or ""), and the image name the YAML records.
void writeTrinaryMapServer(const TrinaryMap& map, const std::string& pgm_path,
                           const std::string& yaml_path, const std::string& preview_png,
                           const std::string& image_name);

/// \brief The centres of the occupied voxels (`occupied` true) or of the free ones.
std::vector<Eigen::Vector3d> voxelCenters(const LogOddsMap& map, bool occupied);

/// \brief The centres of the occupied voxels.
pcl::PointCloud<pcl::PointXYZ> occupiedCenters(const LogOddsMap& map);

}  // namespace metricmap
