#pragma once
/// \file octree_types.h
/// \brief Parameters, nodes and statistics of metricmap::AdaptiveOctree (no PCL needed).

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

namespace metricmap {

/// \brief Deepest level a node can reach: 21 levels fill a 63-bit Morton key. Nodes at this
/// depth are leaves whatever they hold, so identical points, min_cell_size 0 or max_points 0
/// always terminate.
constexpr unsigned kOctreeMaxDepth = 21;

/// \brief AdaptiveOctree parameters.
struct OctreeParams {
  std::size_t max_points_per_leaf = 100;  ///< split while a node holds more than this
  float min_cell_size = 1.0f;             ///< ... and its largest edge is longer than this (>= 0)
  bool cubic_root = false;                ///< root = cube of the largest extent instead of the bbox
  bool has_root_box = false;              ///< use root_min / root_max instead of the cloud's bounds
  Eigen::Vector3d root_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d root_max = Eigen::Vector3d::Zero();
  /// Threads for a build: 0 = all hardware threads, 1 = single-threaded. The nodes, counts and
  /// means do not depend on it (bit for bit). Small clouds use fewer threads.
  unsigned threads = 0;
};

/// \brief Figures of one octree, as in the study's table.
struct OctreeStatistics {
  std::uint64_t total_nodes = 0;
  std::uint64_t leaf_nodes = 0;
  std::uint64_t internal_nodes = 0;
  std::uint64_t occupied_leaves = 0;
  std::uint64_t empty_leaves = 0;
  double mean_points_per_occupied_leaf = 0.0;  ///< points / occupied_leaves (0 when empty)
  std::uint64_t points = 0;                    ///< sum of leaf counts
  unsigned max_depth = 0;                      ///< deepest node (root = 0)
  std::uint64_t skipped_points = 0;  ///< NaN/Inf points, and points outside a given root box
};

/// \brief One node, 48 bytes. Its bounds are not stored: OctreeResult::bounds(id) computes
/// them from the root box and the node's path. A child's bounds halve its parent's at
/// mid = (lo + hi) / 2, in double; a point goes to the upper half of an axis iff its
/// coordinate >= the node's midpoint.
struct OctreeNode {
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();  ///< mean of its points (zero when empty)
  std::uint32_t count = 0;                         ///< points inside
  std::uint32_t first_point = 0;      ///< its points: point_order[first_point, first_point + count)
  std::uint32_t first_child = kNone;  ///< children are first_child .. first_child + 7
  std::uint32_t parent = kNone;
  std::uint32_t depth = 0;  ///< root = 0

  bool isLeaf() const { return first_child == kNone; }
  /// \brief Child `octant` (bit 0: upper x, bit 1: upper y, bit 2: upper z).
  std::size_t child(unsigned octant) const { return std::size_t{first_child} + octant; }
};

/// \brief The axis-aligned box of a node.
struct OctreeBox {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
};

/// \brief The box of child `octant` (bit a set: the upper half along axis a): the halving the
/// build uses, mid = (min + max) / 2 in double, so that every node's box is reproduced exactly.
inline OctreeBox childBox(const OctreeBox& box, unsigned octant) {
  OctreeBox b;
  for (int a = 0; a < 3; ++a) {
    const double mid = (box.min[a] + box.max[a]) / 2;
    const bool upper = (octant >> a) & 1u;
    b.min[a] = upper ? mid : box.min[a];
    b.max[a] = upper ? box.max[a] : mid;
  }
  return b;
}

/// \brief Everything an octree build produces. nodes[0] is the root.
struct OctreeResult {
  std::vector<OctreeNode> nodes;
  std::vector<std::uint32_t> point_order;    ///< input positions, grouped leaf by leaf
  std::vector<std::size_t> occupied_leaves;  ///< node ids in Morton (depth-first) order
  OctreeBox root;                            ///< the root's bounds
  OctreeStatistics stats;

  /// \brief Bounds of node `id`: the root's, halved along the node's path exactly as the build
  /// halves them (bit for bit the boxes the split rule saw). O(depth).
  /// \throws std::out_of_range for an id that is not a node
  OctreeBox bounds(std::size_t id) const;
  /// \brief Bounds of every node, in node order, in one pass from the root down (the same
  /// values as bounds(id)).
  std::vector<OctreeBox> allBounds() const;
};

/// \brief Throws std::invalid_argument for a negative or non-finite min cell size or a bad
/// root box.
void validateOctreeParams(const OctreeParams& params);

/// \brief Scratch memory of an octree build (defined in octree_kernel.h).
struct OctreeWorkspace;

}  // namespace metricmap
