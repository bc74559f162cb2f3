#pragma once
/// \file log_odds_transfer.h
/// \brief A LogOddsMap's voxels as a versioned byte buffer, to build maps per part of the input
/// (other processes, other machines) and merge them with LogOddsMap::merge.
///
/// Merging adds log-odds, so a merged map equals the map of all the scans where no clamping
/// was hit, up to float rounding: one process adds the updates one by one in scan order, the
/// merge adds each part's running sum, and float addition is not associative (differences of a
/// few ulp, ~1e-6 at the clamping bounds; the occupied/free state is the same, since no sum of
/// hits and misses lies within rounding of the threshold). Where clamping was hit the results
/// differ: each part clamps its own sum, and the merge clamps the sum of the clamped parts. A
/// voxel first driven to clamp_min by one part and then hit many times by another ends at
/// clamp(clamp_min + hits) in the merge, but at clamp_max in one process (see the test
/// LogOddsTransfer.ClampingIsPerPart). Both stay within [clamp_min, clamp_max].

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {

/// \brief Every known voxel of `map` and its parameters, block by block (8^3 voxels): per block
/// its key and known bits (72 bytes) and one float per known voxel; 72 bytes of header.
std::vector<std::uint8_t> serializeLogOdds(const LogOddsMap& map);

/// \brief One buffer per owner: buffer k holds the blocks whose voxels tileOwner() gives to part
/// k (tiles are whole blocks). Buffer `keep` (if < parts) holds no block: the caller keeps
/// that part in memory and merges it with mergeOwnedBlocks.
std::vector<std::vector<std::uint8_t>> serializeLogOddsByOwner(const LogOddsMap& map,
                                                               unsigned parts, unsigned keep = ~0u);

/// \brief Merge into `into` the blocks of `from` that tileOwner() gives to `part` of `parts`,
/// as merging buffer `part` of serializeLogOddsByOwner(from, parts) would.
void mergeOwnedBlocks(LogOddsMap& into, const LogOddsMap& from, unsigned part, unsigned parts);

/// \brief Read a buffer written by serializeLogOdds.
/// \throws InputError (naming `what`) when it is truncated, too long, of another format or
/// version, or holds bad parameters, a key outside the key space, a duplicate voxel or a
/// non-finite log-odds
LogOddsMap deserializeLogOdds(const std::uint8_t* data, std::size_t size, const std::string& what);

/// \brief Merge a buffer's voxels straight into `map` (as map.merge(deserializeLogOdds(...)),
/// without the intermediate map). The whole buffer is checked first: on an error `map` is
/// unchanged. A block repeated within the buffer is added twice (not detected here).
/// \throws InputError as deserializeLogOdds, and when the buffer's parameters differ from the map's
void mergeSerializedLogOdds(LogOddsMap& map, const std::uint8_t* data, std::size_t size,
                            const std::string& what);

}  // namespace metricmap
