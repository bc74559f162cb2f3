#pragma once
/// \file split_and_merge_kernel.h
/// \brief The non-template core of SplitAndMerge over 2D points in scan order.

#include <vector>

#include <Eigen/Core>

#include "metricmap/lines/line_segment.h"
#include "metricmap/lines/split_and_merge_types.h"

namespace metricmap {

/// \brief Segments of an ordered 2D scan.
/// \param[in] xy the valid points, in scan order
/// \param[in] beams beam index of each point (same length)
/// \param[in] step optional per-step callback (may be null)
/// \param[out] members for each segment, the beam indices of its points (may be null)
/// \note Thread-safe: no shared state.
std::vector<LineSegment> splitAndMerge(const std::vector<Eigen::Vector2d>& xy,
                                       const std::vector<int>& beams,
                                       const SplitAndMergeParams& params,
                                       const SplitAndMergeStep* step,
                                       std::vector<std::vector<int>>* members);

}  // namespace metricmap
