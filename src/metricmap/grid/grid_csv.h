#pragma once
/// \file grid_csv.h
/// \brief The grid's cells as a CSV table (one row each, header first).

#include <string>
#include <vector>

#include "metricmap/grid/grid_types.h"

namespace metricmap {

/// \brief "ix,iy,iz,count,mean_x,mean_y,mean_z", 9 significant digits.
std::string gridCellsCsv(const std::vector<GridCell>& cells);

}  // namespace metricmap
