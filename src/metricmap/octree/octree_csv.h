#pragma once
/// \file octree_csv.h
/// \brief The octree's leaves as a CSV table (one row each, header first).

#include <string>

#include "metricmap/octree/octree_types.h"

namespace metricmap {

/// \brief "node,depth,min_x,min_y,min_z,max_x,max_y,max_z,count,mean_x,mean_y,mean_z" for every
/// leaf (empty ones too), node = index in the node array; 9 significant digits.
std::string octreeLeavesCsv(const OctreeResult& octree);

}  // namespace metricmap
