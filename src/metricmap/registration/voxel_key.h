#pragma once
/// \file voxel_key.h
/// \brief Integer cell coordinates of a point packed into 64 bits, and their hash.

#include <cmath>
#include <cstdint>

#include <Eigen/Core>

#include "metricmap/exceptions.h"

namespace metricmap {

/// \brief 21 bits per axis: cells from -2^20 to 2^20 - 1 on each axis.
inline std::uint64_t packVoxel(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::int64_t kOffset = std::int64_t{1} << 20;
  return (static_cast<std::uint64_t>(x + kOffset) << 42) |
         (static_cast<std::uint64_t>(y + kOffset) << 21) | static_cast<std::uint64_t>(z + kOffset);
}

/// \brief Throws the CapacityError of a point whose cell lies outside the 21-bit range.
[[noreturn]] void throwVoxelRange(const Eigen::Vector3d& p);

/// \brief Cell of a point already scaled to cell units (`s` = p / voxel), for `p`'s message.
/// \throws CapacityError when the cell lies outside the 21-bit range
inline Eigen::Array3i voxelOfScaled(const Eigen::Array3d& s, const Eigen::Vector3d& p) {
  const Eigen::Array3d c = s.floor();
  constexpr double kLimit = (1 << 20) - 2;  // room for the neighbours of a cell
  if (!(c.abs() < kLimit).all()) throwVoxelRange(p);
  return c.cast<int>();
}

/// \brief Cell of `p` for cells of `inv_voxel`^-1 metres.
/// \throws CapacityError when the cell lies outside the 21-bit range
inline Eigen::Array3i voxelOf(const Eigen::Vector3d& p, double inv_voxel) {
  return voxelOfScaled(p.array() * inv_voxel, p);
}

/// \brief Hash of a packed key (multiplicative, high bits folded down).
struct VoxelKeyHash {
  std::size_t operator()(std::uint64_t k) const {
    k *= 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(k ^ (k >> 29));
  }
};

}  // namespace metricmap
