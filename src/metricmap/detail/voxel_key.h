#pragma once
/// \file voxel_key.h
/// \brief The one voxel key of the library: integer cell coordinates floor(p / cell) per axis,
/// 21 bits each packed in 64 (the log-odds map's voxels and blocks, the odometry's voxel map
/// and downsampling), and the hash their open-addressing tables use.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

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

/// \brief Throws the CapacityError of a point whose cell lies outside the key space.
[[noreturn]] void throwVoxelRange(const Eigen::Vector3d& p);

/// \brief Cell of a point already scaled to cell units (`s` = p / voxel), for `p`'s message.
/// The cell and its neighbours stay inside the key space.
/// \throws CapacityError when the cell lies outside
inline Eigen::Array3i voxelOfScaled(const Eigen::Array3d& s, const Eigen::Vector3d& p) {
  const Eigen::Array3d c = s.floor();
  constexpr double kLimit = static_cast<double>(kVoxelKeyLimit) - 2;  // room for neighbours
  if (!(c.abs() < kLimit).all()) throwVoxelRange(p);
  return c.cast<int>();
}

/// \brief Cell of `p` for cells of `inv_voxel`^-1 metres.
/// \throws CapacityError when the cell lies outside the key space
inline Eigen::Array3i voxelOf(const Eigen::Vector3d& p, double inv_voxel) {
  return voxelOfScaled(p.array() * inv_voxel, p);
}

/// \brief Fibonacci hashing for an open-addressing table of `capacity` (a power of two) slots:
/// the shift that keeps the product's top log2(capacity) bits...
inline int fibonacciShift(std::size_t capacity) {
  int shift = 64;
  for (std::size_t c = capacity; c > 1; c >>= 1) --shift;
  return shift;
}

/// \brief ...and the home slot of a packed key (the product's top bits depend on all of it).
inline std::size_t fibonacciSlot(std::uint64_t key, int shift) {
  return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift);
}

}  // namespace metricmap
