#pragma once
/// \file voxel_key.h
/// \brief World-aligned voxel keys: floor(p / resolution) per axis, 21 bits each, packed in 64.

#include <cstdint>

namespace metricmap {

/// \brief Integer voxel coordinates; voxel k spans [k * res, (k + 1) * res) on each axis.
struct VoxelKey {
  std::int64_t x = 0, y = 0, z = 0;
  bool operator==(const VoxelKey& o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator!=(const VoxelKey& o) const { return !(*this == o); }
};

/// \brief Keys lie in [-kVoxelKeyLimit, kVoxelKeyLimit) on each axis (about +-105 km at 0.1 m).
constexpr std::int64_t kVoxelKeyLimit = std::int64_t{1} << 20;

/// \brief True when every axis of `key` is inside the key space.
inline bool inKeySpace(const VoxelKey& key) {
  return key.x >= -kVoxelKeyLimit && key.x < kVoxelKeyLimit && key.y >= -kVoxelKeyLimit &&
         key.y < kVoxelKeyLimit && key.z >= -kVoxelKeyLimit && key.z < kVoxelKeyLimit;
}

/// \brief 21 bits per axis (offset by kVoxelKeyLimit), x highest. Keys must be in the key space.
inline std::uint64_t packVoxelKey(std::int64_t x, std::int64_t y, std::int64_t z) {
  return (static_cast<std::uint64_t>(x + kVoxelKeyLimit) << 42) |
         (static_cast<std::uint64_t>(y + kVoxelKeyLimit) << 21) |
         static_cast<std::uint64_t>(z + kVoxelKeyLimit);
}

/// \brief Inverse of packVoxelKey.
inline VoxelKey unpackVoxelKey(std::uint64_t packed) {
  constexpr std::uint64_t mask = (std::uint64_t{1} << 21) - 1;
  return {static_cast<std::int64_t>(packed >> 42) - kVoxelKeyLimit,
          static_cast<std::int64_t>((packed >> 21) & mask) - kVoxelKeyLimit,
          static_cast<std::int64_t>(packed & mask) - kVoxelKeyLimit};
}

}  // namespace metricmap
