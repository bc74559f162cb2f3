#pragma once
/// \file simd_points.h
/// \brief x, y, z of one point in an SSE2 register, for the kernels' vector paths (internal).

#include <cstddef>

#include "metricmap/detail/point_span.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace metricmap {

/// \brief True when four floats can be loaded per point: a whole cloud (no index list) of
/// points of 16 bytes or more, which is every PCL point type.
inline bool loadsFourFloats(const PointSpan& points) {
  return points.indices == nullptr && points.stride >= 4 * sizeof(float);
}

#if defined(__SSE2__)
/// \brief x, y, z and the float after them, of point i (needs loadsFourFloats).
inline __m128 loadPoint(const PointSpan& points, std::size_t i) {
  return _mm_loadu_ps(reinterpret_cast<const float*>(reinterpret_cast<const char*>(points.base) +
                                                     i * points.stride));
}

/// \brief x, y and z finite (the fourth lane does not count): v - v is 0 exactly for finite
/// lanes, as in isFinitePoint().
inline bool finiteXyz(__m128 v) {
  return (_mm_movemask_ps(_mm_cmpeq_ps(_mm_sub_ps(v, v), _mm_setzero_ps())) & 7) == 7;
}
#endif

}  // namespace metricmap
