#pragma once
/// \file grid_kernel.h
/// \brief The non-template core of OccupancyGrid: bins a strided float array.

#include "metricmap/detail/key_sorter.h"
#include "metricmap/detail/point_span.h"
#include "metricmap/grid/grid_types.h"

namespace metricmap {

/// \brief Scratch memory of a grid build, kept between builds (fresh pages are costly).
struct GridWorkspace {
  KeySorter sorter;
};

/// \brief Bin the finite points of `points` into cells; NaN/Inf points are skipped and counted.
/// `result` is overwritten (its vectors keep their capacity).
/// \throws CapacityError when the bounding volume has 2^64 cells or more.
/// \note Thread-safe as long as each thread uses its own workspace and result.
void buildGrid(const PointSpan& points, const GridParams& params, GridWorkspace& workspace,
               GridResult& result);

/// \brief Convenience form with a temporary workspace.
GridResult buildGrid(const PointSpan& points, const GridParams& params);

}  // namespace metricmap
