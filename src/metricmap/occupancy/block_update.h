#pragma once
/// \file block_update.h
/// \brief Internals of LogOddsMap: one scan block's hits and misses applied to its map block
/// with OctoMap's update (add, then clamp). Not part of the stable interface.

#include <cstddef>

#include "metricmap/occupancy/block_table.h"

namespace metricmap::detail {

/// \brief The sensor model as log-odds: the hit and miss steps and the clamping bounds.
struct LogOddsStep {
  float hit, miss, lo, hi;
};

/// \brief Voxels newly known, hit and missed by the updates so far.
struct BlockUpdateCounts {
  std::size_t known = 0, hits = 0, misses = 0;
};

/// \brief Apply `scan` to `block`: hits win over misses; a voxel not known before starts at 0.
/// `simd` uses AVX-512F where the CPU has it (the same float operations, the same bits).
void updateBlock(const ScanBlock& scan, VoxelBlock& block, const LogOddsStep& step,
                 BlockUpdateCounts& counts, bool simd);

}  // namespace metricmap::detail
