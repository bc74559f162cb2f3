#pragma once
/// \file voxel_key.h
/// \brief Integer cell coordinates of a point packed into 64 bits, and their hash.

#include <cmath>
#include <cstddef>
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
