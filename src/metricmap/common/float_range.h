#pragma once
/// \file float_range.h
/// \brief Points are stored as float: a double read from a file or computed from an option must
/// fit one. A finite value beyond the float range would become infinite (and the point dropped
/// as if it had no return); a non-zero value below it would become 0 or a subnormal.

#include <cmath>
#include <limits>

namespace metricmap {

/// \brief Finite and larger in magnitude than the largest float (3.40282e+38).
inline bool beyondFloatRange(double v) {
  return std::isfinite(v) && std::abs(v) > static_cast<double>(std::numeric_limits<float>::max());
}

/// \brief Non-zero and smaller in magnitude than the smallest normal float (1.17549e-38).
inline bool belowFloatRange(double v) {
  return v != 0.0 && std::abs(v) < static_cast<double>(std::numeric_limits<float>::min());
}

}  // namespace metricmap
