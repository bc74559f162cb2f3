#pragma once
/// \file tile_owner.h
/// \brief Which of `parts` owns a world-aligned cell: cells are grouped into cubic tiles of
/// 2^shift cells per edge and the tiles are spread over the parts by a hash, so every part
/// agrees on the owner without talking and neighbouring cells travel together.

#include <cstdint>

namespace metricmap {

/// \brief Default tile edge: 2^5 = 32 cells.
constexpr int kTileShift = 5;

/// \brief Owner in [0, parts) of cell (x, y, z); parts > 0.
inline unsigned tileOwner(std::int64_t x, std::int64_t y, std::int64_t z, unsigned parts,
                          int shift = kTileShift) {
  // floor division by 2^shift for negative keys too (arithmetic shift)
  std::uint64_t h = static_cast<std::uint64_t>(x >> shift) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(y >> shift) * 0xC2B2AE3D27D4EB4Full;
  h ^= static_cast<std::uint64_t>(z >> shift) * 0x165667B19E3779F9ull;
  h ^= h >> 31;
  h *= 0xD6E8FEB86659FD93ull;
  h ^= h >> 32;
  return static_cast<unsigned>(h % parts);
}

}  // namespace metricmap
