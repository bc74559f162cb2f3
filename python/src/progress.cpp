#include "progress.h"

namespace metricmap::python {

ProgressWatch::ProgressWatch(const py::object& progress) : last_(std::chrono::steady_clock::now()) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be a callable(done, total) or None, got " +
                         py::repr(progress).cast<std::string>());
  if (!progress.is_none()) progress_ = progress;
}

void ProgressWatch::operator()(std::size_t done, std::size_t total) {
  const auto now = std::chrono::steady_clock::now();
  if (done < total && now - last_ < kInterval) return;
  last_ = now;
  py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  if (progress_) progress_(done, total);
}

}  // namespace metricmap::python
