#pragma once
/// \file occupancy_inputs.h
/// \brief What the inputs of an occupancy run are, told from their paths alone: one OctoMap
/// file to export, one KITTI root, one scan source cast at its reference poses, or PCD scans.

#include <string>
#include <vector>

namespace metricmap {

enum class OccupancyInputKind {
  OctomapFile,  ///< one .bt or .ot map, exported as it is
  KittiRoot,    ///< one folder with sequences/
  ScanSource,   ///< one folder of scans, .txt list, CARMEN log (.clf .log .gz .bz2) or ROS bag
  PcdScans,     ///< anything else: PCD files, each cast from its VIEWPOINT
};

/// \brief The kind of `inputs`; reads nothing but the file system's entries.
OccupancyInputKind occupancyInputKind(const std::vector<std::string>& inputs);

}  // namespace metricmap
