#pragma once
/// \file octomap_quiet.h
/// \brief OctoMap files read and written with stderr muted: liboctomap reports its progress
/// there (" done.", "Reading binary octree ..."), and the command's stderr is for its own
/// one-line errors.

#include <string>

#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/octomap_io.h"

namespace metricmap::cli {

/// \brief readOctomap with `use` (what the caller builds from the voxels) checked against the
/// budget before the tree is expanded.
LogOddsMap readOctomapQuietly(const std::string& path, const OctomapUse& use = OctomapUse());

/// \brief inspectOctomap (the same checks, nothing expanded), quietly.
OctomapExpansion inspectOctomapQuietly(const std::string& path, const OctomapUse& use);

void writeOctomapQuietly(const LogOddsMap& map, const std::string& path);

}  // namespace metricmap::cli
