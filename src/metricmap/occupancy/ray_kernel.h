#pragma once
/// \file ray_kernel.h
/// \brief The hot loop of LogOddsMap::insertScan: one scan's beams walked voxel by voxel
/// (Amanatides & Woo, with OctoMap's arithmetic), misses and hits marked per block, each once.

#include <cstddef>

#include "metricmap/occupancy/block_table.h"

namespace metricmap::detail {

/// \brief One scan: points (3 floats each, `stride_bytes` apart), optional pose (row-major
/// 3x4) mapping them to the world, the sensor origin in the world.
struct RayCastInput {
  const float* xyz = nullptr;
  std::size_t stride_bytes = 12;
  std::size_t count = 0;
  const float* pose = nullptr;
  float origin[3] = {0, 0, 0};
  double resolution = 0.1;
  double max_range = 0.0;  ///< infinity: no cut
  /// Most distinct blocks the scan may touch (the memory budget's share): one more throws
  /// CapacityError naming the resolution and the budget.
  std::size_t max_blocks = static_cast<std::size_t>(-1);
  /// Walk four beams at a time in AVX2 registers where the CPU has AVX2 (the same voxels as
  /// the two-beam SSE2 walk, which `false` forces: for tests).
  bool simd = true;
};

/// \brief Beams cast and skipped.
struct RayCastCounts {
  std::size_t non_finite = 0, beams = 0, cut = 0;
};

/// \brief Mark into `out` (cleared first) the voxels each beam crosses (free) and the endpoint
/// voxels of beams within max_range (hit). Free bits may include hit voxels: the caller lets
/// hits win.
/// \throws CapacityError naming the point when the origin or an endpoint is outside the key
/// space
RayCastCounts castRays(const RayCastInput& in, ScanUpdate& out);

}  // namespace metricmap::detail
