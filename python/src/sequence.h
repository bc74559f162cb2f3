#pragma once
/// \file sequence.h
/// \brief The Python ScanSource object, shared by the sequence, SLAM and mapping bindings.

#include <memory>
#include <mutex>

#include "arrays.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/evaluation/error_statistics.h"
#include "object_lock.h"

namespace metricmap::python {

/// \brief metricmap.ScanSource: the source and the lock that serialises its reads (sources are
/// not thread-safe; every call that reads scans takes it, see object_lock.h).
struct PySource {
  std::unique_ptr<ScanSource> source;
  mutable ObjectMutex mutex;
};

/// \brief `obj` as a ScanSource: the object itself, or a path opened with the defaults (kept
/// alive by `holder`).
PySource& sourceFrom(const py::handle& obj, py::object& holder);

/// \brief count, rmse, mean, median, std, min, max.
py::dict errorStatsDict(const ErrorStatistics& s);

}  // namespace metricmap::python
