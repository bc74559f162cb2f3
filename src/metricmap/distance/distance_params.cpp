#include "metricmap/distance/distance_params.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace metricmap {

std::size_t distanceFieldBytesPerVoxel(const DistanceFieldParams& params) {
  const std::size_t transforms = params.signed_distance ? 2 : 1;
  // state, field, one site mask per transform, then the passes' work arrays
  const std::size_t work = params.incremental ? 8 * transforms : 4;
  return 1 + 4 + transforms + work;
}

void validateDistanceFieldParams(const DistanceFieldParams& params) {
  if (!std::isfinite(params.max_distance) || params.max_distance <= 0.0) {
    std::ostringstream msg;
    msg << "max_distance must be finite and > 0, got " << params.max_distance;
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace metricmap
