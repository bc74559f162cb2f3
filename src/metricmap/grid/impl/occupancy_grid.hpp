#pragma once

#include <algorithm>
#include <tuple>
#include <stdexcept>

#include "metricmap/common/point_span_pcl.h"
#include "metricmap/grid/occupancy_grid.h"

namespace metricmap {

template <typename PointT>
void OccupancyGrid<PointT>::compute() {
  if (!input_) throw std::invalid_argument("OccupancyGrid: no input cloud set");
  const pcl::Indices* idx = (fake_indices_ || !indices_) ? nullptr : indices_.get();
  result_ = buildGrid(makePointSpan(*input_, idx), params_);
}

template <typename PointT>
const GridCell* OccupancyGrid<PointT>::findCell(const std::array<std::int64_t, 3>& index) const {
  const auto before = [](const GridCell& c, const std::array<std::int64_t, 3>& i) {
    return std::make_tuple(c.index[2], c.index[1], c.index[0]) <
           std::make_tuple(i[2], i[1], i[0]);
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
  output.clear();
  output.reserve(result_.cells.size());
  for (const GridCell& c : result_.cells) {
    PointT p = (*input_)[c.first_point];
    p.x = static_cast<float>(c.mean.x());
    p.y = static_cast<float>(c.mean.y());
    p.z = static_cast<float>(c.mean.z());
    output.push_back(p);
  }
  output.width = static_cast<std::uint32_t>(output.size());
  output.height = 1;
  output.is_dense = true;
}

}  // namespace metricmap
