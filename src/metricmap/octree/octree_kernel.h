#pragma once
/// \file octree_kernel.h
/// \brief The non-template core of AdaptiveOctree: a Morton-sorted build over a float array.

#include "metricmap/common/point_span.h"
#include "metricmap/octree/octree_types.h"

namespace metricmap {

/// \brief Throws std::invalid_argument unless min_cell_size is finite and >= 0, and a root
/// box (if any) is finite with max >= min.
void validateOctreeParams(const OctreeParams& params);

/// \brief Build the adaptive octree of the finite points of `points`.
/// A node splits into 8 equal children iff it holds more than max_points_per_leaf points, its
/// largest edge is longer than min_cell_size and its depth is below kOctreeMaxDepth.
/// \note Thread-safe: no shared state.
OctreeResult buildOctree(const PointSpan& points, const OctreeParams& params);

}  // namespace metricmap
