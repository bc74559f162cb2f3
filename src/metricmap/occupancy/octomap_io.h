#pragma once
/// \file octomap_io.h
/// \brief OctoMap files through liboctomap: .bt (maximum likelihood: occupied / free leaves)
/// and .ot (full log-odds). liboctomap stays out of this header.

#include <cstddef>
#include <string>

#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {

/// \brief Write `map` as an OctoMap file chosen by extension: .bt (maximum likelihood, pruned)
/// or .ot (log-odds of every known voxel, pruned where eight siblings agree). Written through
/// a temporary file and a rename.
/// \throws CapacityError when the map does not fit OctoMap's key space (+-32768 voxels per axis)
/// \throws std::invalid_argument for another extension; std::runtime_error naming the file when
/// it cannot be written
void writeOctomap(const LogOddsMap& map, const std::string& path);

/// \brief Read an OctoMap .bt or .ot file (chosen by its first line) into a map with the
/// file's resolution and the sensor model of `params`; pruned leaves are expanded to voxels.
/// .bt leaves take params' clamping bounds as log-odds (liboctomap's convention).
/// \param max_voxels expansion budget (a pruned leaf near the root covers 2^45 voxels)
/// \throws InputError naming the file (missing, corrupt, truncated, not an OcTree)
/// \throws CapacityError when the expansion exceeds max_voxels
LogOddsMap readOctomap(const std::string& path, const LogOddsParams& params = LogOddsParams(),
                       std::size_t max_voxels = std::size_t{1} << 27);

}  // namespace metricmap
