#pragma once
/// \file octree_kernel.h
/// \brief The non-template core of AdaptiveOctree: a Morton-sorted build over a float array.

#include <vector>

#include "metricmap/detail/key_sorter.h"
#include "metricmap/detail/point_span.h"
#include "metricmap/octree/octree_types.h"

namespace metricmap {

/// \brief Scratch memory of an octree build, kept between builds.
struct OctreeWorkspace {
  /// A node waiting to be split or not, with its bounds (nodes do not store them).
  struct Pending {
    std::size_t id;
    OctreeBox box;
  };
  KeySorter sorter;
  std::vector<Pending> stack;
};

/// \brief Build the adaptive octree of the finite points of `points`.
/// A node splits into 8 equal children iff it holds more than max_points_per_leaf points, its
/// largest edge is longer than min_cell_size and its depth is below kOctreeMaxDepth.
/// `result` is overwritten (its vectors keep their capacity).
/// \note Thread-safe as long as each thread uses its own workspace and result.
void buildOctree(const PointSpan& points, const OctreeParams& params, OctreeWorkspace& workspace,
                 OctreeResult& result);

/// \brief Convenience form with a temporary workspace.
OctreeResult buildOctree(const PointSpan& points, const OctreeParams& params);

}  // namespace metricmap
