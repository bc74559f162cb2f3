#include "metricmap/occupancy/block_update.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace metricmap::detail {
namespace {

inline float clampLogOdds(float v, float lo, float hi) {
  // OctoMap's updateNodeLogOdds: add, then clamp below, then above.
  if (v < lo) return lo;
  if (v > hi) return hi;
  return v;
}

void updateBlockPlain(const ScanBlock& sb, VoxelBlock& b, const LogOddsStep& s,
                      BlockUpdateCounts& c) {
  for (int w = 0; w < kBlockWords; ++w) {
    std::uint64_t h = sb.hit[w];
    std::uint64_t f = sb.free[w] & ~h;
    c.known += static_cast<std::size_t>(__builtin_popcountll((h | f) & ~b.known[w]));
    c.hits += static_cast<std::size_t>(__builtin_popcountll(h));
    c.misses += static_cast<std::size_t>(__builtin_popcountll(f));
    const std::uint64_t unknown = ~b.known[w];
    b.known[w] |= h | f;
    float* v = b.log_odds + w * 64;
    while (h != 0) {
      const int i = __builtin_ctzll(h);
      h &= h - 1;
      const float prev = (unknown >> i) & 1 ? 0.0f : v[i];
      v[i] = clampLogOdds(prev + s.hit, s.lo, s.hi);
    }
    while (f != 0) {
      const int i = __builtin_ctzll(f);
      f &= f - 1;
      const float prev = (unknown >> i) & 1 ? 0.0f : v[i];
      v[i] = clampLogOdds(prev + s.miss, s.lo, s.hi);
    }
  }
}

#if defined(__x86_64__)
// GCC 12's AVX-512 headers build constants from _mm512_undefined_*: -Wmaybe-uninitialized
// false positives.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
/// updateBlockPlain sixteen voxels at a time under the words' bit masks: the same float
/// addition, then max with lo and min with hi (clampLogOdds for lo <= hi and finite values).
__attribute__((target("avx512f,popcnt"))) void updateBlockAvx512(const ScanBlock& sb, VoxelBlock& b,
                                                                 const LogOddsStep& s,
                                                                 BlockUpdateCounts& c) {
  const __m512 hit = _mm512_set1_ps(s.hit), miss = _mm512_set1_ps(s.miss);
  const __m512 lo = _mm512_set1_ps(s.lo), hi = _mm512_set1_ps(s.hi);
  for (int w = 0; w < kBlockWords; ++w) {
    const std::uint64_t h = sb.hit[w];
    const std::uint64_t f = sb.free[w] & ~h;
    const std::uint64_t touched = h | f;
    if (touched == 0) continue;
    c.known += static_cast<std::size_t>(__builtin_popcountll(touched & ~b.known[w]));
    c.hits += static_cast<std::size_t>(__builtin_popcountll(h));
    c.misses += static_cast<std::size_t>(__builtin_popcountll(f));
    const std::uint64_t known = b.known[w];
    b.known[w] |= touched;
    float* v = b.log_odds + w * 64;
    for (int q = 0; q < 4; ++q) {
      const auto m = static_cast<__mmask16>(touched >> (16 * q));
      if (m == 0) continue;
      const auto mh = static_cast<__mmask16>(h >> (16 * q));
      const auto mk = static_cast<__mmask16>(known >> (16 * q));
      const __m512 prev = _mm512_maskz_loadu_ps(static_cast<__mmask16>(m & mk), v + 16 * q);
      const __m512 next = _mm512_add_ps(prev, _mm512_mask_blend_ps(mh, miss, hit));
      _mm512_mask_storeu_ps(v + 16 * q, m, _mm512_min_ps(_mm512_max_ps(next, lo), hi));
    }
  }
}

#pragma GCC diagnostic pop

bool haveAvx512f() {
  static const bool yes = __builtin_cpu_supports("avx512f") != 0;
  return yes;
}
#endif

}  // namespace

void updateBlock(const ScanBlock& scan, VoxelBlock& block, const LogOddsStep& step,
                 BlockUpdateCounts& counts, bool simd) {
#if defined(__x86_64__)
  if (simd && haveAvx512f()) {
    updateBlockAvx512(scan, block, step, counts);
    return;
  }
#endif
  updateBlockPlain(scan, block, step, counts);
}

}  // namespace metricmap::detail
