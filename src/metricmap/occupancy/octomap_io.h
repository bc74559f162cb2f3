#pragma once
/// \file octomap_io.h
/// \brief OctoMap files through liboctomap: .bt (maximum likelihood: occupied / free leaves)
/// and .ot (full log-odds). liboctomap stays out of this header.

#include <cstddef>
#include <cstdint>
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

/// \brief What the caller of readOctomap builds from the expanded voxels: bytes per occupied and
/// per free voxel (a cube in the viewer, a point of an exported cloud, a node of a rewritten
/// OctoMap tree), checked with the map's own blocks against the memory budget before a single
/// voxel is expanded. A file of a few dozen bytes can describe 2^27 voxels.
struct OctomapUse {
  std::uint64_t bytes_per_occupied_voxel = 0;
  std::uint64_t bytes_per_free_voxel = 0;
  std::string purpose;  ///< named in the message, e.g. "drawn as cubes"
};

/// \brief The voxels a file's tree expands to, counted from its leaves without expanding them.
struct OctomapExpansion {
  std::uint64_t voxels = 0, occupied_voxels = 0, free_voxels = 0;
  std::uint64_t blocks = 0;     ///< 8^3-voxel blocks of the expanded map
  std::uint64_t map_bytes = 0;  ///< the expanded LogOddsMap
  std::uint64_t use_bytes = 0;  ///< what OctomapUse adds
};

/// \brief Read an OctoMap .bt or .ot file (chosen by its first line) into a map with the
/// file's resolution and the sensor model of `params`; pruned leaves are expanded to voxels.
/// .bt leaves take params' clamping bounds as log-odds (liboctomap's convention).
/// \param max_voxels expansion budget (a pruned leaf near the root covers 2^45 voxels)
/// \throws InputError naming the file (missing, corrupt, truncated, not an OcTree)
/// \throws CapacityError when the expansion exceeds max_voxels
LogOddsMap readOctomap(const std::string& path, const LogOddsParams& params = LogOddsParams(),
                       std::size_t max_voxels = std::size_t{1} << 27);

/// \brief readOctomap with the caller's use of the voxels checked first: the map and `use`
/// together must fit the memory budget (checkMemory), else CapacityError naming the file, the
/// voxel counts and `use.purpose`, before any expansion. `expansion` (if not null) receives the
/// counts.
LogOddsMap readOctomap(const std::string& path, const LogOddsParams& params, const OctomapUse& use,
                       std::size_t max_voxels = std::size_t{1} << 27,
                       OctomapExpansion* expansion = nullptr);

/// \brief The checks of readOctomap(path, params, use, max_voxels) without the expansion: what
/// the file's tree expands to, or the same exceptions. Reads the file (bounded by its size).
OctomapExpansion inspectOctomap(const std::string& path,
                                const LogOddsParams& params = LogOddsParams(),
                                const OctomapUse& use = OctomapUse(),
                                std::size_t max_voxels = std::size_t{1} << 27);

}  // namespace metricmap
