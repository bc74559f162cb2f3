#pragma once
/// \file scene_content.h
/// \brief What the viewer draws for a cloud: the adaptive octree's leaves or the grid's cells
/// as boxes with their point counts (no VTK here).

#include <cstddef>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/grid/grid_types.h"
#include "metricmap/octree/octree_types.h"
#include "metricmap/viz/scene_types.h"

namespace metricmap::viz {

struct OctreeBoxes {
  std::vector<CountedBox> boxes;     ///< leaves (occupied ones, or all with show_empty)
  std::vector<double> point_counts;  ///< per point: the count of its leaf
  OctreeStatistics statistics;
};

/// \brief Build the adaptive octree of `cloud` and return its leaves as boxes.
OctreeBoxes octreeBoxes(const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& cloud,
                        std::size_t max_points, float min_cell_size, bool show_empty);

struct GridBoxes {
  std::vector<CountedBox> boxes;  ///< occupied cells
  GridStatistics statistics;
};

/// \brief Build the occupancy grid of `cloud` (cloud-minimum origin) and return its cells.
GridBoxes gridBoxes(const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& cloud, float cell_size);

}  // namespace metricmap::viz
