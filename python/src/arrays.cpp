#include <pybind11/stl.h>

#include "arrays.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "metricmap/exceptions.h"

namespace metricmap::python {

namespace {

/// numpy's kind letter: b(ool), i, u, f, c, O, S, U, V, M, m.
char kindOf(const py::array& a) { return a.dtype().kind(); }

void requireRealNumeric(const py::array& a, const char* name) {
  const char k = kindOf(a);
  if (k != 'f' && k != 'i' && k != 'u' && k != 'b') {
    std::ostringstream msg;
    msg << name << " must be an array of real numbers, got dtype "
        << py::str(a.dtype()).cast<std::string>();
    if (k == 'O')
      msg << " (rows of different lengths, or objects numpy cannot read as numbers; give an "
             "(N, 3) array of numbers, or an object with .points such as an Open3D PointCloud)";
    throw py::type_error(msg.str());
  }
}

py::array asArray(const py::handle& obj, const char* name) {
  if (py::isinstance<py::array>(obj)) return py::reinterpret_borrow<py::array>(obj);
  try {
    return py::module_::import("numpy").attr("asarray")(obj);
  } catch (py::error_already_set& e) {
    std::ostringstream msg;
    msg << name << " must be an array of numbers: " << e.what();
    throw py::type_error(msg.str());
  }
}

bool readInPlace(const py::array& a) {
  if (!a.dtype().is(py::dtype::of<float>())) return false;  // float32, native byte order
  const auto flags = py::detail::array_proxy(a.ptr())->flags;
  if (!(flags & py::detail::npy_api::NPY_ARRAY_ALIGNED_)) return false;
  const py::ssize_t cols = a.shape(1);
  if (a.strides(1) != static_cast<py::ssize_t>(sizeof(float))) return false;
  const py::ssize_t row = a.strides(0);
  if (a.shape(0) <= 1) return true;
  // C-contiguous rows of 3 or 4 floats; rows of 4 further apart (a view of every k-th row).
  // Rows of 3 further apart are copied: the vector path loads 4 floats per point.
  return row == cols * static_cast<py::ssize_t>(sizeof(float)) ||
         (cols == 4 && row > 0 && row % static_cast<py::ssize_t>(sizeof(float)) == 0);
}

}  // namespace

py::object pointsOf(const py::handle& obj) {
  if (!py::isinstance<py::array>(obj) && !py::isinstance<py::list>(obj) &&
      !py::isinstance<py::tuple>(obj) && py::hasattr(obj, "points"))
    return obj.attr("points");
  return py::reinterpret_borrow<py::object>(obj);
}

PointsArray pointsFromArray(const py::handle& obj, const char* name, bool allow_empty) {
  py::array a = asArray(pointsOf(obj), name);
  requireRealNumeric(a, name);
  if (a.ndim() != 2 || (a.shape(1) != 3 && a.shape(1) != 4)) {
    std::ostringstream msg;
    msg << name << " must have shape (N, 3) or (N, 4), got (";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) msg << (i ? ", " : "") << a.shape(i);
    msg << (a.ndim() == 1 ? ",)" : ")");
    throw py::value_error(msg.str());
  }
  if (a.shape(0) == 0 && !allow_empty)
    throw py::value_error(std::string(name) + " is empty (0 points)");
  PointsArray out;
  out.columns = static_cast<std::size_t>(a.shape(1));
  if (readInPlace(a)) {
    out.array = a;
  } else {
    if (kindOf(a) == 'f' && a.itemsize() > 4) {
      // float64 -> float32: a finite coordinate beyond float32's range does not fit (checked
      // before the cast, which would make it infinite and so skipped as non-finite).
      CArray<double> d(a);
      const double* v = d.data();
      const std::size_t n = static_cast<std::size_t>(d.size());
      constexpr double kMax = std::numeric_limits<float>::max();
      for (std::size_t i = 0; i < n; ++i) {
        if (std::isfinite(v[i]) && std::abs(v[i]) > kMax) {
          std::ostringstream msg;
          msg << name << ": coordinate " << v[i] << " (row " << i / out.columns
              << ") does not fit float32, the precision metricmap computes in";
          throw py::value_error(msg.str());
        }
      }
    }
    out.array = CArray<float>(a);
    out.copied = true;
  }
  out.span.base = static_cast<const float*>(out.array.data());
  out.span.stride = static_cast<std::size_t>(out.array.shape(0) > 1 ? out.array.strides(0)
                                                                    : out.columns * sizeof(float));
  out.span.size = static_cast<std::size_t>(out.array.shape(0));
  return out;
}

CArray<double> doublesFromArray(const py::handle& obj, const char* name) {
  py::array a = asArray(obj, name);
  requireRealNumeric(a, name);
  return CArray<double>(a);
}

py::array_t<double> matrix4(const Eigen::Matrix4d& m) {
  py::array_t<double> a({4, 4});
  auto r = a.mutable_unchecked<2>();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = m(i, j);
  return a;
}

Eigen::Matrix4d matrix4From(const py::handle& obj, const char* name) {
  auto a = doublesFromArray(obj, name);
  if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
    throw py::value_error(std::string(name) + " must have shape (4, 4)");
  Eigen::Matrix4d m;
  auto r = a.unchecked<2>();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m(i, j) = r(i, j);
  if (!m.allFinite()) throw py::value_error(std::string(name) + " must be finite");
  return m;
}

Eigen::Vector3d vector3From(const py::handle& obj, const char* name) {
  auto a = doublesFromArray(obj, name);
  if (a.size() != 3 || a.ndim() > 1)
    throw py::value_error(std::string(name) + " must have 3 elements (x, y, z)");
  Eigen::Vector3d v(a.data()[0], a.data()[1], a.data()[2]);
  if (!v.allFinite()) throw py::value_error(std::string(name) + " must be finite");
  return v;
}

void raiseOSError(const std::exception& e) {
  PyErr_SetString(PyExc_OSError, e.what());
  throw py::error_already_set();
}

void registerExceptions(py::module_& m) {
  py::object type = py::module_::import("builtins").attr("type");
  // Classes with two built-in bases, so that `except OSError` / `except ValueError` both work.
  // Leaked on purpose: the translator may run until the interpreter's very end.
  static PyObject* input_error =
      type("InputError", py::make_tuple(py::handle(PyExc_OSError), py::handle(PyExc_ValueError)),
           py::dict(py::arg("__module__") = "metricmap",
                    py::arg("__doc__") = "A file or scan could not be read (OSError, ValueError)."))
          .release()
          .ptr();
  static PyObject* capacity_error =
      type("CapacityError",
           py::make_tuple(py::handle(PyExc_MemoryError), py::handle(PyExc_ValueError)),
           py::dict(py::arg("__module__") = "metricmap",
                    py::arg("__doc__") = "A result would not fit (MemoryError, ValueError)."))
          .release()
          .ptr();
  m.attr("InputError") = py::handle(input_error);
  m.attr("CapacityError") = py::handle(capacity_error);
  py::register_local_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(input_error, e.what());
    } catch (const CapacityError& e) {
      // The library names the CLI's option; a Python user sets the budget by a function.
      std::string text = e.what();
      const std::string option = "--max-memory", function = "metricmap.set_memory_budget";
      for (std::size_t at = text.find(option); at != std::string::npos;
           at = text.find(option, at + function.size()))
        text.replace(at, option.size(), function);
      PyErr_SetString(capacity_error, text.c_str());
    }
  });
}

std::vector<double> beamVector(const py::handle& obj, const char* name) {
  auto a = doublesFromArray(obj, name);
  if (a.ndim() != 1) throw py::value_error(std::string(name) + " must be 1-D, shape (B,)");
  return {a.data(), a.data() + a.size()};
}

}  // namespace metricmap::python
