#include "metricmap/detail/bounds.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "metricmap/detail/parallel.h"
#include "metricmap/detail/simd_points.h"

namespace metricmap {
namespace {

void scalarBounds(const PointSpan& points, float lo[3], float hi[3], std::size_t& finite) {
  for (std::size_t i = 0; i < points.size; ++i) {
    const float* p = points.at(i);
    if (!isFinitePoint(p)) continue;
    ++finite;
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
}

#if defined(__SSE2__)
/// x, y, z (and one more float, ignored) per point in one register (needs loadsFourFloats).
void sseBounds(const PointSpan& points, float lo[3], float hi[3], std::size_t& finite) {
  __m128 vlo = _mm_setr_ps(lo[0], lo[1], lo[2], 0.0f);
  __m128 vhi = _mm_setr_ps(hi[0], hi[1], hi[2], 0.0f);
  for (std::size_t i = 0; i < points.size; ++i) {
    const __m128 v = loadPoint(points, i);
    if (!finiteXyz(v)) continue;
    ++finite;
    vlo = _mm_min_ps(vlo, v);
    vhi = _mm_max_ps(vhi, v);
  }
  alignas(16) float l[4], h[4];
  _mm_store_ps(l, vlo);
  _mm_store_ps(h, vhi);
  for (int a = 0; a < 3; ++a) {
    lo[a] = l[a];
    hi[a] = h[a];
  }
}
#endif

}  // namespace

Bounds computeBounds(const PointSpan& points) {
  Bounds b;
  float lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<float>::max();
    hi[a] = std::numeric_limits<float>::lowest();
  }
#if defined(__SSE2__)
  if (loadsFourFloats(points)) {
    sseBounds(points, lo, hi, b.finite);
  } else {
    scalarBounds(points, lo, hi, b.finite);
  }
#else
  scalarBounds(points, lo, hi, b.finite);
#endif
  if (b.finite == 0) return b;
  for (int a = 0; a < 3; ++a) {
    b.min[a] = lo[a];
    b.max[a] = hi[a];
  }
  return b;
}

PointSpan slice(const PointSpan& points, std::size_t begin, std::size_t end) {
  PointSpan s = points;
  s.size = end - begin;
  if (points.indices != nullptr) {
    s.indices = points.indices + begin;
  } else {
    s.base = reinterpret_cast<const float*>(reinterpret_cast<const char*>(points.base) +
                                            begin * points.stride);
  }
  return s;
}

Bounds computeBounds(const PointSpan& points, unsigned threads) {
  if (threads <= 1) return computeBounds(points);
  std::vector<Bounds> parts(threads);
  parallelRun(threads, [&](unsigned t) {
    const auto [begin, end] = chunkOf(points.size, threads, t);
    parts[t] = computeBounds(slice(points, begin, end));
  });
  Bounds b;
  for (const Bounds& part : parts) {
    if (part.finite == 0) continue;
    for (int a = 0; a < 3; ++a) {
      b.min[a] = b.finite == 0 ? part.min[a] : std::min(b.min[a], part.min[a]);
      b.max[a] = b.finite == 0 ? part.max[a] : std::max(b.max[a], part.max[a]);
    }
    b.finite += part.finite;
  }
  return b;
}

}  // namespace metricmap
