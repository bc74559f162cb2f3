#pragma once
/// \file format_number.h
/// \brief A number as it may appear in a message: the shortest `%g` text that reads back as the
/// same value (`1e+308`, `0.0001`, `0.1`), never `inf` for a finite value, never the 309 digits or
/// the `0.000000` of `std::to_string`.

#include <cstdio>
#include <cstdlib>
#include <string>

namespace metricmap {

/// \brief Shortest round-trip `%g` text of `value` ("nan", "inf" and "-inf" as such); whole
/// numbers below 1e16 in plain digits (`90`, `100000`, not `9e+01`, `1e+05`).
inline std::string formatNumber(double value) {
  char buf[40];
  int digits = 1;
  for (; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (std::strtod(buf, nullptr) == value) break;
  }
  const double magnitude = value < 0 ? -value : value;
  if (magnitude >= 10 && magnitude < 1e16) {  // enough digits for %g to write it plainly
    int whole = 1;
    for (double m = magnitude; m >= 10; m /= 10) ++whole;
    std::snprintf(buf, sizeof buf, "%.*g", whole > digits ? whole : digits, value);
  }
  return buf;
}

/// \brief Shortest round-trip `%g` text of a float (0.1f as "0.1", not 0.100000001...).
inline std::string formatNumber(float value) {
  char buf[40];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, static_cast<double>(value));
    if (std::strtof(buf, nullptr) == value) break;
  }
  return buf;
}

}  // namespace metricmap
