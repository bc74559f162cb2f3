#pragma once
/// \file cell_means.h
/// \brief The mean point of every cell as a cloud, as OccupancyGrid::filter makes them.

#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/grid/grid_types.h"

namespace metricmap {

/// \brief One point per cell of `cells` (its mean, as float), in their order; a dense,
/// unorganised cloud.
pcl::PointCloud<pcl::PointXYZ> cellMeans(const std::vector<GridCell>& cells);

}  // namespace metricmap
