#pragma once
/// \file octomap_quiet.h
/// \brief OctoMap files read and written with stderr muted: liboctomap reports its progress
/// there (" done.", "Reading binary octree ..."), and a caller's stderr is for its own messages.
/// The process's stderr descriptor is redirected for the call's duration.

#include <string>

#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/octomap_io.h"

namespace metricmap {

/// \brief readOctomap, quietly.
LogOddsMap readOctomapQuietly(const std::string& path, const LogOddsParams& params = {},
                              const OctomapUse& use = OctomapUse());

/// \brief inspectOctomap, quietly.
OctomapExpansion inspectOctomapQuietly(const std::string& path, const LogOddsParams& params,
                                       const OctomapUse& use);

/// \brief writeOctomap, quietly.
void writeOctomapQuietly(const LogOddsMap& map, const std::string& path);

}  // namespace metricmap
