#pragma once

#include <stdexcept>
#include <type_traits>

#include <pcl/point_types.h>

#include "metricmap/detail/huge_pages.h"
#include "metricmap/detail/point_span_pcl.h"
#include "metricmap/octree/adaptive_octree.h"
#include "metricmap/octree/octree_kernel.h"

namespace metricmap {

template <typename PointT>
void AdaptiveOctree<PointT>::setMinCellSize(float min_cell_size) {
  OctreeParams p = params_;
  p.min_cell_size = min_cell_size;
  validateOctreeParams(p);
  params_ = p;
}

template <typename PointT>
void AdaptiveOctree<PointT>::setRootBox(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  OctreeParams p = params_;
  p.has_root_box = true;
  p.root_min = min;
  p.root_max = max;
  validateOctreeParams(p);
  params_ = p;
}

template <typename PointT>
void AdaptiveOctree<PointT>::compute() {
  if (!input_) throw std::invalid_argument("AdaptiveOctree: no input cloud set");
  const pcl::Indices* idx = (fake_indices_ || !indices_) ? nullptr : indices_.get();
  buildOctree(makePointSpan(*input_, idx), params_, workspace_.get(), result_);
}

template <typename PointT>
std::vector<int> AdaptiveOctree<PointT>::getPointIndices(std::size_t node_id) const {
  const OctreeNode& n = result_.nodes.at(node_id);
  const auto first = result_.point_order.begin() + static_cast<std::ptrdiff_t>(n.first_point);
  return std::vector<int>(first, first + static_cast<std::ptrdiff_t>(n.count));
}

template <typename PointT>
void AdaptiveOctree<PointT>::applyFilter(PointCloud& output) {
  compute();
  const std::vector<std::size_t>& leaves = result_.occupied_leaves;
  reserveHuge(output.points, leaves.size());
  output.resize(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    const OctreeNode& n = result_.nodes[leaves[i]];
    PointT& p = output[i];
    if constexpr (!std::is_same_v<PointT, pcl::PointXYZ>) {
      p = (*input_)[result_.point_order[n.first_point]];
    }
    p.x = static_cast<float>(n.mean.x());
    p.y = static_cast<float>(n.mean.y());
    p.z = static_cast<float>(n.mean.z());
  }
  output.width = static_cast<std::uint32_t>(output.size());
  output.height = 1;
  output.is_dense = true;
}

}  // namespace metricmap
