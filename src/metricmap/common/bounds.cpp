#include "metricmap/common/bounds.h"

#include <algorithm>
#include <limits>

namespace metricmap {

Bounds computeBounds(const PointSpan& points) {
  Bounds b;
  float lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<float>::max();
    hi[a] = std::numeric_limits<float>::lowest();
  }
  for (std::size_t i = 0; i < points.size; ++i) {
    const float* p = points.at(i);
    if (!isFinitePoint(p)) continue;
    ++b.finite;
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  if (b.finite == 0) return b;
  for (int a = 0; a < 3; ++a) {
    b.min[a] = lo[a];
    b.max[a] = hi[a];
  }
  return b;
}

}  // namespace metricmap
