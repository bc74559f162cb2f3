#pragma once
/// \file grid_kernel.h
/// \brief The non-template core of OccupancyGrid: bins a strided float array.

#include "metricmap/common/point_span.h"
#include "metricmap/grid/grid_types.h"

namespace metricmap {

/// \brief Throws std::invalid_argument unless the cell size is finite and > 0.
void validateCellSize(float cell_size);

/// \brief Bin the finite points of `points` into cells; NaN/Inf points are skipped and counted.
/// \throws CapacityError when the bounding volume has 2^64 cells or more.
/// \note Thread-safe: no shared state; call concurrently on different inputs.
GridResult buildGrid(const PointSpan& points, const GridParams& params);

}  // namespace metricmap
