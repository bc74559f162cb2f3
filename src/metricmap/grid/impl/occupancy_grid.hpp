#pragma once

#include <algorithm>
#include <tuple>

#include <pcl/point_types.h>
#include <stdexcept>

#include "metricmap/detail/huge_pages.h"
#include "metricmap/detail/point_span_pcl.h"
#include "metricmap/grid/cell_means.h"
#include "metricmap/grid/grid_kernel.h"
#include "metricmap/grid/occupancy_grid.h"

namespace metricmap {

template <typename PointT>
void OccupancyGrid<PointT>::compute() {
  if (!input_) throw std::invalid_argument("OccupancyGrid: no input cloud set");
  const pcl::Indices* idx = (fake_indices_ || !indices_) ? nullptr : indices_.get();
  buildGrid(makePointSpan(*input_, idx), params_, workspace_.get(), result_);
}

template <typename PointT>
const GridCell* OccupancyGrid<PointT>::findCell(const std::array<std::int64_t, 3>& index) const {
  const auto before = [](const GridCell& c, const std::array<std::int64_t, 3>& i) {
    return std::make_tuple(c.index[2], c.index[1], c.index[0]) < std::make_tuple(i[2], i[1], i[0]);
  };
  auto it = std::lower_bound(result_.cells.begin(), result_.cells.end(), index, before);
  return (it != result_.cells.end() && it->index == index) ? &*it : nullptr;
}

template <typename PointT>
Eigen::Vector3d OccupancyGrid<PointT>::getCellMin(const std::array<std::int64_t, 3>& index) const {
  const GridLayout& L = result_.layout;
  return L.origin + L.cell_size * Eigen::Vector3d(static_cast<double>(index[0]),
                                                  static_cast<double>(index[1]),
                                                  static_cast<double>(index[2]));
}

template <typename PointT>
void OccupancyGrid<PointT>::applyFilter(PointCloud& output) {
  compute();
  reserveHuge(output.points, result_.cells.size());
  fillCellMeans(result_.cells, input_.get(), output);
}

}  // namespace metricmap
