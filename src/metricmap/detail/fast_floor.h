#pragma once
/// \file fast_floor.h
/// \brief floor() to an integer without a libm call (baseline x86-64 has no SSE4.1 round).

#include <cstdint>

namespace metricmap {

/// \brief Exactly std::floor(v) as an integer, for finite |v| < 2^62.
inline std::int64_t floorToInt(float v) {
  const auto t = static_cast<std::int64_t>(v);
  return t - static_cast<std::int64_t>(v < static_cast<float>(t));
}

/// \brief Exactly std::floor(v) as an integer, for finite |v| < 2^62.
inline std::int64_t floorToInt(double v) {
  const auto t = static_cast<std::int64_t>(v);
  return t - static_cast<std::int64_t>(v < static_cast<double>(t));
}

}  // namespace metricmap
