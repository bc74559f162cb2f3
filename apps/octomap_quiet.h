#pragma once
/// \file octomap_quiet.h
/// \brief OctoMap files read and written with stderr muted: liboctomap reports its progress
/// there (" done.", "Reading binary octree ..."), and the command's stderr is for its own
/// one-line errors.

#include <string>

#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap::cli {

LogOddsMap readOctomapQuietly(const std::string& path);
void writeOctomapQuietly(const LogOddsMap& map, const std::string& path);

}  // namespace metricmap::cli
