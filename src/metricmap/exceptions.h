#pragma once
/// \file exceptions.h
/// \brief Errors thrown by metricmap: bad parameters, unreadable input, sizes that do not fit.

#include <stdexcept>
#include <string>

namespace metricmap {

/// \brief A file could not be read as a point cloud. The message names the file.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// \brief A result would not fit (64-bit cell counts, memory); the message gives the size.
class CapacityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace metricmap
