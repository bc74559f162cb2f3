#pragma once
/// \file bounds.h
/// \brief Axis-aligned bounds of the finite points of a PointSpan.

#include <cstddef>

#include "metricmap/detail/point_span.h"

namespace metricmap {

/// \brief Bounds over finite points; `finite` counts them (0 leaves min/max unset).
struct Bounds {
  float min[3] = {0.0f, 0.0f, 0.0f};
  float max[3] = {0.0f, 0.0f, 0.0f};
  std::size_t finite = 0;
};

/// \brief One pass over the view; NaN/Inf points are not counted.
Bounds computeBounds(const PointSpan& points);

/// \brief The same over `threads` contiguous chunks at once (min/max: any thread count gives
/// the same bounds).
Bounds computeBounds(const PointSpan& points, unsigned threads);

/// \brief Points [begin, end) of a view, as a view.
PointSpan slice(const PointSpan& points, std::size_t begin, std::size_t end);

/// \brief True when x, y and z are all finite.
inline bool isFinitePoint(const float* p) {
  return (p[0] - p[0] == 0.0f) && (p[1] - p[1] == 0.0f) && (p[2] - p[2] == 0.0f);
}

}  // namespace metricmap
