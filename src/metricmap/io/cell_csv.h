#pragma once
/// \file cell_csv.h
/// \brief The grid's cells and the octree's leaves as CSV tables (one row each, header first).

#include <string>
#include <vector>

#include "metricmap/grid/grid_types.h"
#include "metricmap/octree/octree_types.h"

namespace metricmap {

/// \brief "ix,iy,iz,count,mean_x,mean_y,mean_z", 9 significant digits.
std::string gridCellsCsv(const std::vector<GridCell>& cells);

/// \brief "node,depth,min_x,min_y,min_z,max_x,max_y,max_z,count,mean_x,mean_y,mean_z" for every
/// leaf (empty ones too), node = index in the node array; 9 significant digits.
std::string octreeLeavesCsv(const OctreeResult& octree);

}  // namespace metricmap
