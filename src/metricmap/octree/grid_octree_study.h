#pragma once
/// \file grid_octree_study.h
/// \brief The grid-vs-octree study of one cloud: the occupancy grid and the adaptive octree
/// built over it with one configuration, their statistics and build times.

#include <cstddef>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/grid/grid_types.h"
#include "metricmap/octree/octree_types.h"

namespace metricmap {

/// \brief What the study gives for one cloud and configuration.
struct GridOctreeFigures {
  GridStatistics grid;
  OctreeStatistics octree;
  double grid_s = 0.0, octree_s = 0.0;  ///< build seconds
};

/// \brief Build the grid of `cloud` (cells of `cell_size`, cloud-minimum origin) and its
/// octree (split above `max_points`, nodes down to `min_cell_size`).
/// \throws what OccupancyGrid and AdaptiveOctree throw for bad parameters
GridOctreeFigures gridOctreeFigures(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                                    float cell_size, float min_cell_size, std::size_t max_points);

}  // namespace metricmap
