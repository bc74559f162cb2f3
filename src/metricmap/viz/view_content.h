#pragma once
/// \file view_content.h
/// \brief What the 3D viewer is given from its inputs (no VTK here): a 2D scan as grey points,
/// an occupancy map's voxels as cubes, the octree's leaves or the grid's cells as boxes.

#include <cstddef>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/viz/scene_types.h"

namespace metricmap {
class LogOddsMap;
}

namespace metricmap::viz {

/// \brief Append the finite points of a 2D scan to `out` at z = 0, light grey (200, 200, 200).
void appendScanPoints(const pcl::PointCloud<pcl::PointXYZ>& scan,
                      pcl::PointCloud<pcl::PointXYZRGB>& out);

/// \brief Add the occupied voxels of `map` to `occupied` (and its free ones to `free` when
/// `with_free`); both layers take the map's resolution.
/// \throws InputError naming `name` when `occupied` already holds voxels of another resolution
void addMapVoxels(const LogOddsMap& map, const std::string& name, bool with_free,
                  VoxelLayer& occupied, VoxelLayer& free);

/// \brief What the structures over the merged cloud draw.
struct StructureBoxes {
  std::vector<CountedBox> boxes;     ///< octree leaves, then grid cells
  std::vector<double> point_counts;  ///< with the octree: per point, the count of its leaf
  std::string
      title;  ///< " | octree max_points M, min_cell C: O occupied / L leaves", " | grid ..."
};

/// \brief Settings of the structures drawn over the points.
struct StructureSettings {
  bool octree = false;  ///< the adaptive octree's leaves
  std::size_t max_points = 100;
  float min_cell_size = 1.0f;
  bool show_empty = false;  ///< also empty leaves
  bool grid = false;        ///< the occupied grid cells
  float cell_size = 1.0f;
};

/// \brief The octree's leaves and/or the grid's cells of `cloud`, with the title's part.
StructureBoxes structureBoxes(const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& cloud,
                              const StructureSettings& settings);

}  // namespace metricmap::viz
