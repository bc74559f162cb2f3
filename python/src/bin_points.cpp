// metricmap.bin_points: Active Neural SLAM's numpy bin_points (the library's mapping/bin_points.h).
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/mapping/bin_points.h"

namespace metricmap::python {

namespace {

template <typename T>
py::tuple run(const py::array& xyz, const BinPointsParams& params) {
  const py::ssize_t nd = xyz.ndim();
  std::vector<py::ssize_t> batch(xyz.shape(), xyz.shape() + nd - 3);
  const std::size_t h = static_cast<std::size_t>(xyz.shape(nd - 3));
  const std::size_t w = static_cast<std::size_t>(xyz.shape(nd - 2));
  const std::size_t channels = static_cast<std::size_t>(xyz.shape(nd - 1));
  std::size_t frames = 1;
  for (py::ssize_t b : batch) frames *= static_cast<std::size_t>(b);
  const py::ssize_t m = static_cast<py::ssize_t>(params.map_size);
  const py::ssize_t nz = static_cast<py::ssize_t>(params.z_bins.size() + 1);
  // priced before any array exists: counts (8 bytes a cell and bin), valid (1 byte a pixel), and
  // a C-ordered copy of the input when it is not one already (a broadcast view)
  __extension__ typedef unsigned __int128 U128;  // GCC/Clang; __extension__: no -Wpedantic
  const U128 words = static_cast<U128>(frames) * static_cast<std::uint64_t>(m) *
                         static_cast<std::uint64_t>(m) * static_cast<std::uint64_t>(nz) +
                     (static_cast<U128>(frames) * h * w * (1 + channels * sizeof(T))) / 8 + 1;
  const std::uint64_t cap = ~std::uint64_t{0} / 16;  // beyond any budget
  checkMemory(words > cap ? cap : static_cast<std::uint64_t>(words), 8,
              "bin_points: " + std::to_string(frames) + " frame(s) of " + std::to_string(m) +
                  " x " + std::to_string(m) + " x " + std::to_string(nz) + " bins");
  CArray<T> a(xyz);
  std::vector<py::ssize_t> counts_shape = batch, valid_shape = batch;
  counts_shape.insert(counts_shape.end(), {m, m, nz});
  valid_shape.insert(valid_shape.end(), {py::ssize_t(h), py::ssize_t(w), 1});
  // numpy.zeros: calloc'd, so the kernel faults in only the pages its points land on (a map of
  // 480 x 480 x 3 bins is 5.3 MiB, most of it never written by one frame)
  py::array_t<double> counts =
      py::module_::import("numpy").attr("zeros")(py::cast(counts_shape), "float64");
  py::array_t<bool> valid(valid_shape);
  double* c = counts.mutable_data();
  bool* v = valid.mutable_data();
  const T* p = a.data();
  {
    py::gil_scoped_release release;
    binPoints<T>(p, frames, h * w, channels, params, c, v);
  }
  return py::make_tuple(counts, valid);
}

}  // namespace

void initBinPoints(py::module_& m) {
  m.def(
      "bin_points",
      [](ArrayLike XYZ, std::int64_t map_size, ArrayLike z_bins, double xy_resolution) {
        BinPointsParams params;
        params.map_size = map_size;
        params.xy_resolution = xy_resolution;
        auto bins = doublesFromArray(z_bins, "z_bins");
        if (bins.ndim() > 1) throw py::value_error("z_bins must be one-dimensional");
        params.z_bins.assign(bins.data(), bins.data() + bins.size());
        validateBinPointsParams(params);
        py::array a = py::isinstance<py::array>(XYZ)
                          ? py::reinterpret_borrow<py::array>(XYZ)
                          : py::array(py::module_::import("numpy").attr("asarray")(XYZ));
        const char kind = a.dtype().kind();
        if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
          throw py::type_error("XYZ must be an array of real numbers, got dtype " +
                               py::str(a.dtype()).cast<std::string>());
        if (a.ndim() < 3 || a.shape(a.ndim() - 1) < 3)
          throw py::value_error("XYZ must have shape (..., H, W, C) with C >= 3");
        if (a.shape(a.ndim() - 3) == 0 || a.shape(a.ndim() - 2) == 0)
          throw py::value_error("XYZ has no pixels (H or W is 0)");
        if (a.dtype().is(py::dtype::of<float>()) || (kind == 'f' && a.itemsize() < 4))
          return run<float>(a, params);
        return run<double>(a, params);  // float64, and int/bool (numpy divides them in float64)
      },
      py::arg("XYZ"), py::arg("map_size"), py::arg("z_bins"), py::arg("xy_resolution"), R"doc(
Active Neural SLAM's ``bin_points``: count points per (y bin, x bin, height bin).

Equal, dtype and shape included, to the numpy function of Active Neural SLAM
(env/utils/depth_utils.py; Chaplot et al., ICLR 2020) returning ``(counts, isvalids)`` as its
ancestor in Gupta et al.'s cognitive mapping code does, for float32 and float64 input:
``X_bin = np.round(x / xy_resolution).astype(np.int32)`` (halves to even; the division in the
input's precision), ``Y_bin`` likewise, ``Z_bin = np.digitize(z, z_bins)``; a point counts iff
``0 <= X_bin, Y_bin < map_size`` and x is not NaN (a NaN z lands in the top bin).

Parameters
----------
XYZ : array_like, shape (..., H, W, C), C >= 3
    Points (x, y, z in the first three channels), e.g. centimetres; any leading batch dims.
map_size : int
    Cells per side (> 0).
z_bins : array_like, shape (B,)
    Monotonic height edges (np.digitize's bins).
xy_resolution : float
    Cell edge in XYZ's unit (finite, non-zero).

Returns
-------
counts : numpy.ndarray, float64, shape (..., map_size, map_size, B + 1)
    Points per [y bin, x bin, height bin] (np.bincount's float64 counts).
isvalid : numpy.ndarray, bool, shape (..., H, W, 1)
    Which points were counted.

Raises
------
ValueError
    map_size <= 0, a zero/non-finite resolution, z_bins not monotonic or with NaN, a map of
    2**31 bins or more, XYZ without (H, W, C >= 3) trailing dims (numpy would fail or
    overflow there too).
TypeError
    a non-numeric dtype.
)doc");
}

}  // namespace metricmap::python
