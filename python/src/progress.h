#pragma once
/// \file progress.h
/// \brief Progress reports and Ctrl-C for calls that run long with the GIL released.

#include <chrono>
#include <cstddef>

#include "arrays.h"

namespace metricmap::python {

/// \brief Called by the library between scans (without the GIL): at most every kInterval and
/// at the last scan, it takes the GIL, runs Python's signal handlers (a pending Ctrl-C raises
/// KeyboardInterrupt) and then the user's `progress(done, total)`. An exception from either
/// leaves the library's loop as py::error_already_set and reaches the caller as itself. Made and
/// destroyed with the GIL held (outside the call's gil_scoped_release).
class ProgressWatch {
 public:
  /// \brief `progress`: None or a callable(done, total). \throws py::type_error otherwise
  explicit ProgressWatch(const py::object& progress);
  ProgressWatch(const ProgressWatch&) = delete;
  ProgressWatch& operator=(const ProgressWatch&) = delete;

  void operator()(std::size_t done, std::size_t total);

  static constexpr std::chrono::milliseconds kInterval{20};

 private:
  py::object progress_;  // touched only with the GIL held
  std::chrono::steady_clock::time_point last_;
};

}  // namespace metricmap::python
