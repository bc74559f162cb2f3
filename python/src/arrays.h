#pragma once
/// \file arrays.h
/// \brief numpy <-> library glue shared by the binding files: point arrays viewed in the
/// layout the kernels read (no copy when possible), result arrays as views of C++ objects,
/// and the module's exception classes.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <Eigen/Core>

#include "metricmap/detail/point_span.h"

namespace metricmap::python {

namespace py = pybind11;

/// \brief numpy's flags for "C-contiguous, aligned, native byte order, this dtype": an array
/// converts to CArray<T> without a copy only when it already is all of these (pybind11's
/// c_style | forcecast alone lets an unaligned array through, whose loads are undefined).
constexpr int kCArrayFlags =
    py::array::c_style | py::array::forcecast | py::detail::npy_api::NPY_ARRAY_ALIGNED_;
template <typename T>
using CArray = py::array_t<T, kCArrayFlags>;

/// \brief Any Python object a numpy array can be made of (an array, a list, ...); shown as
/// numpy.typing.ArrayLike in signatures. The functions check and convert it themselves.
struct ArrayLike {
  py::object obj;
  operator const py::handle&() const { return obj; }
};

/// \brief x, y, z of an (N, 3) or (N, 4) array as a PointSpan, and the array it reads.
///
/// A float32 array whose rows are 3 or 4 contiguous, aligned, native-endian floats is read in
/// place: C-contiguous (N, 3) and (N, 4), and (N, 4) rows with a larger positive row stride
/// (e.g. every other row). Anything else of a real numeric dtype (float64, int, a transposed or
/// sliced view) is converted once to a C-contiguous float32 array of its own shape.
struct PointsArray {
  PointSpan span;
  py::array array;      ///< what `span` points into (the caller's array or the copy)
  bool copied = false;  ///< true when the input had to be converted
  std::size_t columns = 0;
};

/// \brief The points of `obj`: itself, or its `.points` when it is not an array, list or tuple
/// but has them (an Open3D PointCloud, a metricmap Scan: duck-typed, Open3D is not needed).
py::object pointsOf(const py::handle& obj);

/// \brief View `obj` as points (see PointsArray): an array, a list, or an object with a
/// `.points` that is one (an Open3D PointCloud, duck-typed). `name` is used in messages.
/// \throws py::type_error for a non-numeric dtype (complex, object, strings) or a non-array
/// \throws py::value_error for another shape, no rows (unless allow_empty), or a finite
/// float64 coordinate that float32 cannot hold (|x| > 3.4e38)
PointsArray pointsFromArray(const py::handle& obj, const char* name, bool allow_empty = false);

/// \brief A 1-D or N-D float64 copy of `obj` (any real numeric dtype), C-contiguous.
/// \throws py::type_error as pointsFromArray
CArray<double> doublesFromArray(const py::handle& obj, const char* name);

/// \brief A 1-D array of a scan's beams (angles or ranges) as doubles.
/// \throws py::value_error "NAME must be 1-D, shape (B,)" for another shape
std::vector<double> beamVector(const py::handle& obj, const char* name);

/// \brief A read-only array viewing `data` (owned by `owner`, kept alive by the array).
template <typename T>
py::array viewOf(const T* data, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
                 const py::handle& owner) {
  if (data == nullptr) return py::array(py::dtype::of<T>(), std::move(shape));  // no elements
  py::array a(py::dtype::of<T>(), std::move(shape), std::move(strides), data, owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

/// \brief A new array owning a copy of `values` reshaped to `shape`.
template <typename T>
py::array_t<T> arrayFrom(const std::vector<T>& values, std::vector<py::ssize_t> shape) {
  py::array_t<T> a(shape);
  if (!values.empty()) std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

/// \brief A 4x4 matrix as a new (4, 4) float64 array.
py::array_t<double> matrix4(const Eigen::Matrix4d& m);

/// \brief A (4, 4) array of finite numbers as a matrix. \throws py::value_error otherwise
Eigen::Matrix4d matrix4From(const py::handle& obj, const char* name);

/// \brief A length-3 array of finite numbers. \throws py::value_error otherwise
Eigen::Vector3d vector3From(const py::handle& obj, const char* name);

/// \brief Register metricmap.InputError (OSError and ValueError), metricmap.CapacityError
/// (MemoryError and ValueError) and the translation of the library's exceptions.
void registerExceptions(py::module_& m);

/// \brief Raise OSError with the message of a library error about a file.
[[noreturn]] void raiseOSError(const std::exception& e);

}  // namespace metricmap::python

namespace pybind11::detail {
template <>
struct type_caster<metricmap::python::ArrayLike> {
  PYBIND11_TYPE_CASTER(metricmap::python::ArrayLike, const_name("numpy.typing.ArrayLike"));
  bool load(handle src, bool) {
    if (!src) return false;
    value.obj = reinterpret_borrow<object>(src);
    return true;
  }
  static handle cast(const metricmap::python::ArrayLike& v, return_value_policy, handle) {
    return v.obj.inc_ref();
  }
};
}  // namespace pybind11::detail
