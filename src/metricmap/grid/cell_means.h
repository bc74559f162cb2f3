#pragma once
/// \file cell_means.h
/// \brief The mean point of every cell as a cloud, as OccupancyGrid::filter makes them.

#include <cstdint>
#include <type_traits>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/grid/grid_types.h"

namespace metricmap {

/// \brief Fill `output` with one point per cell of `cells`, in their order: the cell's first
/// point of `input` (its non-coordinate fields; not read for PointXYZ, where `input` may be
/// null) at the cell's mean (as float); a dense, unorganised cloud. OccupancyGrid::filter's
/// output.
template <typename PointT>
void fillCellMeans(const std::vector<GridCell>& cells, const pcl::PointCloud<PointT>* input,
                   pcl::PointCloud<PointT>& output) {
  output.resize(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    PointT& p = output[i];
    if constexpr (!std::is_same_v<PointT, pcl::PointXYZ>) p = (*input)[cells[i].first_point];
    p.x = static_cast<float>(cells[i].mean.x());
    p.y = static_cast<float>(cells[i].mean.y());
    p.z = static_cast<float>(cells[i].mean.z());
  }
  output.width = static_cast<std::uint32_t>(output.size());
  output.height = 1;
  output.is_dense = true;
}

/// \brief One point per cell of `cells` (its mean, as float), in their order; a dense,
/// unorganised cloud.
pcl::PointCloud<pcl::PointXYZ> cellMeans(const std::vector<GridCell>& cells);

}  // namespace metricmap
