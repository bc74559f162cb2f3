#include "metricmap/distance/distance_params.h"

#include <cmath>
#include <limits>
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
  // The field is float32: a bound that rounds to zero (or to a subnormal) would write 0, the
  // distance of an occupied voxel, everywhere.
  if (params.max_distance < static_cast<double>(std::numeric_limits<float>::min())) {
    std::ostringstream msg;
    msg << "max_distance " << params.max_distance << " m is below the smallest float32 distance ("
        << std::numeric_limits<float>::min()
        << " m): the field would read 0, as if occupied, everywhere";
    throw std::invalid_argument(msg.str());
  }
  if (params.max_distance > static_cast<double>(std::numeric_limits<float>::max())) {
    std::ostringstream msg;
    msg << "max_distance " << params.max_distance << " m is beyond float32's range";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace metricmap
