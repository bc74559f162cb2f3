#pragma once
/// \file octomap_export_use.h
/// \brief What exporting an OctoMap file builds per expanded voxel (OctomapUse), so that the
/// budget is checked before the tree is expanded (a 30-byte tree can stand for 2^27 voxels).

#include <string>
#include <vector>

#include "metricmap/occupancy/octomap_io.h"

namespace metricmap {

/// \brief The use of exporting a tree as the OctoMap files named in `tree_outputs` (an OctoMap
/// tree before pruning per voxel, however many are written) and the occupied voxel centres as
/// the clouds named in `cloud_outputs`; the purpose names them all ("exported as --out and
/// --out-cloud"), none: an empty use.
OctomapUse octomapExportUse(const std::vector<std::string>& tree_outputs,
                            const std::vector<std::string>& cloud_outputs);

}  // namespace metricmap
