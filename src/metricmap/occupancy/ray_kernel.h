#pragma once
/// \file ray_kernel.h
/// \brief The hot loop of LogOddsMap::insertScan: one scan's beams walked voxel by voxel
/// (Amanatides & Woo, with OctoMap's arithmetic), misses and hits marked per block, each once.
///
/// Two walks give the same voxels, bit for bit: the SIMD walk (x86-64: SSE2, four beams per
/// AVX2 register where the CPU has AVX2) and the portable walk (plain C++, the same double
/// arithmetic and the same tie-breaking between axes), the only one compiled on other CPUs
/// (aarch64, ...). setRayPathForTesting forces the portable walk on x86 for tests and benchmarks.

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
  /// Most beams walked at once on the SIMD path: 8 in AVX-512 registers where the CPU has
  /// AVX-512F, else 4 in AVX2 registers where it has AVX2, else 2 (SSE2). Every width marks the
  /// same voxels; a smaller value forces a narrower walk (for tests and benchmarks). The
  /// portable walk ignores it.
  int lanes = 8;
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

/// \brief Unite `from`'s marks into `into` (blocks new to `into` appended in `from`'s order).
/// \throws CapacityError as castRays does when `into` would exceed max_blocks
void uniteScanUpdates(ScanUpdate& into, const ScanUpdate& from, std::size_t max_blocks,
                      double resolution);

/// \brief The walks castRays can take; both mark the same voxels, bit for bit.
enum class RayPath {
  Simd,      ///< the default: SSE2 (x86-64), four-lane AVX2 where the CPU has it
  Portable,  ///< plain C++ in double, any CPU
};

/// \brief The walk the next castRays takes: always Portable where the SIMD walks are not
/// compiled (anything but x86-64 with SSE2, e.g. aarch64), else the last setRayPathForTesting
/// value (Simd at start).
RayPath rayPath();

/// \brief The widest walk castRays takes on this CPU with `lanes` = 8 and RayPath::Simd:
/// "avx512 (8 lanes)", "avx2 (4 lanes)", "sse2 (2 lanes)" or "portable" (for reports).
const char* simdWalkName();

/// \brief Forces the walk of every later castRays in the process, so that CI can run the
/// portable walk on x86 and benchmarks can compare the two. A relaxed atomic that castRays
/// reads once per scan (never per beam or voxel): any thread may call it; a scan being cast
/// keeps the walk it started with. Not for production code; restore the default with
/// ScopedRayPath.
void setRayPathForTesting(RayPath path);

/// \brief Sets the RayPath for a scope and restores the previous one when it ends.
class ScopedRayPath {
 public:
  explicit ScopedRayPath(RayPath path) : previous_(rayPath()) { setRayPathForTesting(path); }
  ~ScopedRayPath() { setRayPathForTesting(previous_); }
  ScopedRayPath(const ScopedRayPath&) = delete;
  ScopedRayPath& operator=(const ScopedRayPath&) = delete;

 private:
  RayPath previous_;
};

}  // namespace metricmap::detail
