#pragma once
// The plain reference for distance fields: for every voxel, the nearest obstacle found by
// trying every voxel of the box (and the box's walls when space beyond it is an obstacle).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "metricmap/distance/distance_params.h"

namespace metricmap::testing {

/// Squared distance (voxel units) from voxel (i, j, k) to the nearest voxel beyond the box.
inline std::int64_t wallDistance2(const std::array<std::size_t, 3>& n, int dims, std::int64_t i,
                                  std::int64_t j, std::int64_t k) {
  const std::int64_t c[3] = {i, j, k};
  std::int64_t best = std::numeric_limits<std::int64_t>::max();
  for (int a = 0; a < dims; ++a) {
    best = std::min(best, std::min(c[a] + 1, static_cast<std::int64_t>(n[a]) - c[a]));
  }
  return best * best;
}

/// The field by brute force: states, the obstacle rule, clamping and signs as DistanceField
/// documents them.
inline std::vector<float> bruteForceField(const OccupancyBox& box, const DistanceFieldParams& p) {
  const auto& n = box.shape;
  const auto obstacle = [&](std::uint8_t s) {
    return s == kVoxelOccupied || (s == kVoxelUnknown && p.unknown == UnknownAs::Occupied);
  };
  const bool outside_obstacle = p.unknown == UnknownAs::Occupied;
  std::vector<float> out(box.voxels());
  const auto at = [&](std::size_t i, std::size_t j, std::size_t k) {
    return (i * n[1] + j) * n[2] + k;
  };
  for (std::size_t i = 0; i < n[0]; ++i) {
    for (std::size_t j = 0; j < n[1]; ++j) {
      for (std::size_t k = 0; k < n[2]; ++k) {
        const bool self = obstacle(box.state[at(i, j, k)]);
        // unsigned: distance to obstacles; signed obstacle voxels: to non-obstacles, negated
        const bool want = !(p.signed_distance && self);
        std::int64_t best = std::numeric_limits<std::int64_t>::max();
        for (std::size_t x = 0; x < n[0]; ++x) {
          for (std::size_t y = 0; y < n[1]; ++y) {
            for (std::size_t z = 0; z < n[2]; ++z) {
              if (obstacle(box.state[at(x, y, z)]) != want) continue;
              const std::int64_t dx = static_cast<std::int64_t>(x) - static_cast<std::int64_t>(i);
              const std::int64_t dy = static_cast<std::int64_t>(y) - static_cast<std::int64_t>(j);
              const std::int64_t dz = static_cast<std::int64_t>(z) - static_cast<std::int64_t>(k);
              best = std::min(best, dx * dx + dy * dy + dz * dz);
            }
          }
        }
        if (outside_obstacle == want) {
          best = std::min(
              best, wallDistance2(n, box.dimensions, static_cast<std::int64_t>(i),
                                  static_cast<std::int64_t>(j), static_cast<std::int64_t>(k)));
        }
        double d = p.max_distance;
        if (best != std::numeric_limits<std::int64_t>::max()) {
          d = std::min(p.max_distance, std::sqrt(static_cast<double>(best)) * box.resolution);
        }
        out[at(i, j, k)] = static_cast<float>(want ? d : -d);
      }
    }
  }
  return out;
}

}  // namespace metricmap::testing
