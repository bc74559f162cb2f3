#pragma once
/// \file adaptive_octree.h
/// \brief metricmap::AdaptiveOctree — an octree that splits dense regions, as a PCL filter.

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

#include <pcl/filters/filter.h>

#include "metricmap/common/scratch.h"
#include "metricmap/octree/octree_types.h"

namespace metricmap {

/// \brief Adaptive octree over a cloud (count + mean per node); `filter()` gives the mean of
/// each occupied leaf, in depth-first (Morton) order. Non-coordinate fields are those of the
/// leaf's first point.
///
/// The root is the cloud's axis-aligned bounding box (or the cube of its largest extent with
/// setCubicRoot(true), or a box given with setRootBox). A node splits into 8 equal children iff
/// it holds more than max_points points AND its largest edge is longer than min_cell_size AND
/// its depth is below kOctreeMaxDepth (21). All 8 children exist. A point goes to the upper
/// half of an axis iff its coordinate >= the midpoint, so points on the root's max faces land in
/// the last child and every point lies in exactly one leaf.
///
/// The build sorts 63-bit Morton keys (radix sort) and cuts the sorted run top-down.
/// \note Thread safety: one instance per thread; different instances share nothing.
template <typename PointT>
class AdaptiveOctree : public pcl::Filter<PointT> {
 protected:
  using pcl::Filter<PointT>::filter_name_;
  using pcl::Filter<PointT>::input_;
  using pcl::Filter<PointT>::indices_;
  using pcl::Filter<PointT>::fake_indices_;

 public:
  using PointCloud = typename pcl::Filter<PointT>::PointCloud;
  using Ptr = std::shared_ptr<AdaptiveOctree<PointT>>;
  using ConstPtr = std::shared_ptr<const AdaptiveOctree<PointT>>;

  AdaptiveOctree() { filter_name_ = "AdaptiveOctree"; }

  /// \brief Split while a node holds more than this many points.
  void setMaxPointsPerLeaf(std::size_t max_points) { params_.max_points_per_leaf = max_points; }
  std::size_t getMaxPointsPerLeaf() const { return params_.max_points_per_leaf; }

  /// \brief Do not split nodes whose largest edge is <= this (metres).
  /// \throws std::invalid_argument unless finite and >= 0
  void setMinCellSize(float min_cell_size);
  float getMinCellSize() const { return params_.min_cell_size; }

  /// \brief Root = cube of the largest extent, anchored at the cloud's minimum (default false).
  void setCubicRoot(bool cubic) { params_.cubic_root = cubic; }
  bool getCubicRoot() const { return params_.cubic_root; }

  /// \brief Use this root box instead of the cloud's bounds; points outside are skipped and
  /// counted in OctreeStatistics::skipped_points.
  /// \throws std::invalid_argument unless finite with max >= min
  void setRootBox(const Eigen::Vector3d& min, const Eigen::Vector3d& max);

  /// \brief Build the tree without producing a cloud (filter() does this too).
  /// \throws std::invalid_argument without an input cloud
  /// \brief Threads for a build, in PCL's manner: 0 = all hardware threads (default), 1 = one.
  /// The result does not depend on it, bit for bit. Clouds under ~130 k points per thread use
  /// fewer threads.
  void setNumberOfThreads(unsigned threads) { params_.threads = threads; }
  unsigned getNumberOfThreads() const { return params_.threads; }

  void compute();

  /// \brief pcl::Filter::filter, except that without an input cloud it throws, as compute()
  /// does, instead of returning quietly with the output untouched.
  /// \throws std::invalid_argument without an input cloud; CapacityError when too large
  void filter(PointCloud& output) {
    if (!input_) throw std::invalid_argument(filter_name_ + ": no input cloud set");
    pcl::Filter<PointT>::filter(output);
  }

  const OctreeStatistics& getStatistics() const { return result_.stats; }
  /// \brief All nodes of the last build; index 0 is the root.
  const std::vector<OctreeNode>& getNodes() const { return result_.nodes; }
  /// \brief Bounds of node `node_id` (nodes do not store them; see OctreeResult::bounds).
  /// \throws std::out_of_range for an id that is not a node
  OctreeBox getNodeBounds(std::size_t node_id) const { return result_.bounds(node_id); }
  /// \brief Everything the last build produced: nodes, point order, leaves, root box, figures.
  const OctreeResult& getResult() const { return result_; }
  /// \brief Node ids of the occupied leaves, depth-first.
  const std::vector<std::size_t>& getOccupiedLeaves() const { return result_.occupied_leaves; }
  /// \brief Input positions of a node's points.
  std::vector<int> getPointIndices(std::size_t node_id) const;

 protected:
  void applyFilter(PointCloud& output) override;

 private:
  OctreeParams params_;
  Scratch<OctreeWorkspace> workspace_;  // kept between builds
  OctreeResult result_;
};

}  // namespace metricmap

#ifdef METRICMAP_NO_PRECOMPILE
#include "metricmap/octree/impl/adaptive_octree.hpp"
#else
// The library instantiates every type of PCL_XYZ_POINT_TYPES; these three are the common ones.
#include <pcl/point_types.h>
extern template class metricmap::AdaptiveOctree<pcl::PointXYZ>;
extern template class metricmap::AdaptiveOctree<pcl::PointXYZI>;
extern template class metricmap::AdaptiveOctree<pcl::PointXYZRGB>;
#endif
