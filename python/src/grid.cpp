// metricmap.grid: OccupancyGrid's kernel on a numpy array; cells as views of the result.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <pybind11/stl.h>

#include "arrays.h"
#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/grid/grid_kernel.h"

namespace metricmap::python {

namespace {

constexpr const char* kOrigins = "'cloud-min', 'world', 'open3d' or a point (x, y, z)";

/// origin= : a convention by name, or the start of cell (0, 0, 0) as three numbers.
void parseOrigin(const py::object& origin, GridParams& params) {
  if (py::isinstance<py::str>(origin)) {
    const std::string name = origin.cast<std::string>();
    if (name == "cloud-min") {
      params.origin = GridOrigin::CloudMinimum;
    } else if (name == "world") {
      params.origin = GridOrigin::WorldAligned;
    } else if (name == "open3d") {
      params.origin = GridOrigin::HalfCellBelowMinimum;
    } else {
      throw py::value_error(std::string("origin must be ") + kOrigins + ", got '" + name + "'");
    }
    return;
  }
  std::vector<double> xyz;
  try {
    xyz = origin.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string("origin must be ") + kOrigins + ", got " +
                         std::string(py::str(py::type::of(origin).attr("__name__"))));
  }
  if (xyz.size() != 3)
    throw py::value_error(std::string("origin must be ") + kOrigins + ", got " +
                          std::to_string(xyz.size()) + " numbers");
  for (double v : xyz)
    if (!std::isfinite(v))
      throw py::value_error("origin must be finite, got " + std::string(py::str(py::repr(origin))));
  params.origin = GridOrigin::Point;
  params.origin_point = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
}

py::dict statisticsDict(const GridStatistics& s) {
  py::dict d;
  d["total_cells"] = s.total_cells;
  d["occupied_cells"] = s.occupied_cells;
  d["empty_cells"] = s.empty_cells;
  d["mean_points_per_occupied_cell"] = s.mean_points_per_occupied_cell;
  d["points"] = s.points;
  d["skipped_points"] = s.skipped_points;
  return d;
}

/// The grid's state for pickle: layout (min_index, dims, origin, cell_size), statistics, and
/// the cells as arrays: indices (M, 3) int64, counts (M,) uint64, means (M, 3) float64,
/// first_points (M,) uint64.
py::tuple gridState(const GridResult& r) {
  const GridLayout& l = r.layout;
  const GridStatistics& st = r.stats;
  const py::ssize_t n = static_cast<py::ssize_t>(r.cells.size());
  py::array_t<std::int64_t> indices({n, py::ssize_t(3)});
  py::array_t<std::uint64_t> counts(n), first(n);
  py::array_t<double> means({n, py::ssize_t(3)});
  for (py::ssize_t i = 0; i < n; ++i) {
    const GridCell& c = r.cells[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      indices.mutable_at(i, k) = c.index[k];
      means.mutable_at(i, k) = c.mean[k];
    }
    counts.mutable_at(i) = c.count;
    first.mutable_at(i) = c.first_point;
  }
  return py::make_tuple(
      py::make_tuple(l.min_index[0], l.min_index[1], l.min_index[2], l.dims[0], l.dims[1],
                     l.dims[2], l.origin.x(), l.origin.y(), l.origin.z(), l.cell_size),
      py::make_tuple(st.total_cells, st.occupied_cells, st.empty_cells,
                     st.mean_points_per_occupied_cell, st.points, st.skipped_points),
      indices, counts, means, first,
      r.point_cells.empty()
          ? py::object(py::none())
          : py::object(py::array_t<std::int64_t>(static_cast<py::ssize_t>(r.point_cells.size()),
                                                 r.point_cells.data())));
}

std::shared_ptr<GridResult> gridFromState(const py::tuple& t) {
  if (t.size() != 6 && t.size() != 7) throw py::value_error("Grid: not a pickled grid");
  const py::tuple l = t[0], st = t[1];
  if (l.size() != 10 || st.size() != 6) throw py::value_error("Grid: not a pickled grid");
  auto r = std::make_shared<GridResult>();
  for (int k = 0; k < 3; ++k) {
    r->layout.min_index[k] = l[k].cast<std::int64_t>();
    r->layout.dims[k] = l[3 + k].cast<std::uint64_t>();
    r->layout.origin[k] = l[6 + k].cast<double>();
  }
  r->layout.cell_size = l[9].cast<double>();
  r->stats = GridStatistics{st[0].cast<std::uint64_t>(), st[1].cast<std::uint64_t>(),
                            st[2].cast<std::uint64_t>(), st[3].cast<double>(),
                            st[4].cast<std::uint64_t>(), st[5].cast<std::uint64_t>()};
  constexpr int kC = py::array::c_style | py::array::forcecast;
  const auto indices = py::array_t<std::int64_t, kC>(t[2]);
  const auto counts = py::array_t<std::uint64_t, kC>(t[3]);
  const auto means = py::array_t<double, kC>(t[4]);
  const auto first = py::array_t<std::uint64_t, kC>(t[5]);
  const py::ssize_t n = counts.size();
  if (indices.ndim() != 2 || indices.shape(0) != n || indices.shape(1) != 3 || means.ndim() != 2 ||
      means.shape(0) != n || means.shape(1) != 3 || first.size() != n)
    throw py::value_error("Grid: not a pickled grid");
  r->cells.resize(static_cast<std::size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) {
    GridCell& c = r->cells[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      c.index[k] = indices.at(i, k);
      c.mean[k] = means.at(i, k);
    }
    c.count = counts.at(i);
    c.first_point = static_cast<std::size_t>(first.at(i));
  }
  if (t.size() == 7 && !t[6].is_none()) {
    const auto rows = py::array_t<std::int64_t, kC>(t[6]);
    r->point_cells.assign(rows.data(), rows.data() + rows.size());
  }
  return r;
}

bool sameGrid(const GridResult& a, const GridResult& b) {
  const GridLayout &p = a.layout, &q = b.layout;
  const GridStatistics &s = a.stats, &t = b.stats;
  if (p.min_index != q.min_index || p.dims != q.dims || p.origin != q.origin ||
      p.cell_size != q.cell_size || s.total_cells != t.total_cells ||
      s.occupied_cells != t.occupied_cells || s.empty_cells != t.empty_cells ||
      s.mean_points_per_occupied_cell != t.mean_points_per_occupied_cell || s.points != t.points ||
      s.skipped_points != t.skipped_points || a.cells.size() != b.cells.size() ||
      a.point_cells != b.point_cells)
    return false;
  for (std::size_t i = 0; i < a.cells.size(); ++i) {
    const GridCell &c = a.cells[i], &d = b.cells[i];
    if (c.index != d.index || c.count != d.count || c.mean != d.mean ||
        c.first_point != d.first_point)
      return false;
  }
  return true;
}

}  // namespace

void initGrid(py::module_& m) {
  py::class_<GridResult, std::shared_ptr<GridResult>>(m, "Grid", R"doc(
The occupied cells of a grid build (see :func:`grid`), in linear-index order (x fastest).

The array properties are read-only views of the cells held by this object; they keep it alive.
)doc")
      .def_property_readonly(
          "statistics", [](const GridResult& r) { return statisticsDict(r.stats); },
          "dict: total_cells, occupied_cells, empty_cells, mean_points_per_occupied_cell, points, "
          "skipped_points (the study's figures).")
      .def_property_readonly(
          "indices",
          [](py::object self) {
            const auto& r = self.cast<const GridResult&>();
            return viewOf<std::int64_t>(
                r.cells.empty() ? nullptr : r.cells[0].index.data(),
                {py::ssize_t(r.cells.size()), 3},
                {py::ssize_t(sizeof(GridCell)), py::ssize_t(sizeof(std::int64_t))}, self);
          },
          "(M, 3) int64 view: integer cell index of each occupied cell.")
      .def_property_readonly(
          "counts",
          [](py::object self) {
            const auto& r = self.cast<const GridResult&>();
            return viewOf<std::uint64_t>(r.cells.empty() ? nullptr : &r.cells[0].count,
                                         {py::ssize_t(r.cells.size())},
                                         {py::ssize_t(sizeof(GridCell))}, self);
          },
          "(M,) uint64 view: points in each occupied cell.")
      .def_property_readonly(
          "means",
          [](py::object self) {
            const auto& r = self.cast<const GridResult&>();
            return viewOf<double>(r.cells.empty() ? nullptr : r.cells[0].mean.data(),
                                  {py::ssize_t(r.cells.size()), 3},
                                  {py::ssize_t(sizeof(GridCell)), py::ssize_t(sizeof(double))},
                                  self);
          },
          "(M, 3) float64 view: mean of each occupied cell's points, metres.")
      .def_property_readonly(
          "first_points",
          [](py::object self) {
            const auto& r = self.cast<const GridResult&>();
            return viewOf<std::size_t>(r.cells.empty() ? nullptr : &r.cells[0].first_point,
                                       {py::ssize_t(r.cells.size())},
                                       {py::ssize_t(sizeof(GridCell))}, self);
          },
          "(M,) uint64 view: row of the input of each cell's first point.")
      .def_property_readonly(
          "point_cells",
          [](py::object self) -> py::object {
            const auto& r = self.cast<const GridResult&>();
            if (r.point_cells.empty()) return py::none();
            return viewOf<std::int64_t>(r.point_cells.data(), {py::ssize_t(r.point_cells.size())},
                                        {py::ssize_t(sizeof(std::int64_t))}, self);
          },
          "(N,) int64 view or None: per input point the row of its cell in the cell arrays "
          "(numpy's np.unique(..., return_inverse=True)), -1 for a skipped NaN/Inf point; "
          "None unless grid(..., point_cells=True).")
      .def_property_readonly(
          "min_index",
          [](const GridResult& r) {
            return py::make_tuple(r.layout.min_index[0], r.layout.min_index[1],
                                  r.layout.min_index[2]);
          },
          "(ix, iy, iz): index of the lowest cell per axis.")
      .def_property_readonly(
          "dims",
          [](const GridResult& r) {
            return py::make_tuple(r.layout.dims[0], r.layout.dims[1], r.layout.dims[2]);
          },
          "(nx, ny, nz): cells per axis of the bounding volume.")
      .def_property_readonly(
          "origin",
          [](const GridResult& r) {
            return py::make_tuple(r.layout.origin.x(), r.layout.origin.y(), r.layout.origin.z());
          },
          "(x, y, z): world position of cell index (0, 0, 0), metres.")
      .def_property_readonly(
          "cell_size", [](const GridResult& r) { return r.layout.cell_size; }, "Cell edge, metres.")
      .def("__len__", [](const GridResult& r) { return r.cells.size(); })
      .def(py::pickle(&gridState, &gridFromState))
      .def(
          "__eq__",
          [](const GridResult& self, const py::object& other) {
            return py::isinstance<GridResult>(other) &&
                   sameGrid(self, other.cast<const GridResult&>());
          },
          py::is_operator())
      .def("__repr__", [](const GridResult& r) {
        return "<metricmap.Grid " + std::to_string(r.cells.size()) + " occupied of " +
               std::to_string(r.stats.total_cells) + " cells>";
      });

  m.def(
      "grid",
      [](ArrayLike points, double cell_size, const py::object& origin, unsigned threads,
         bool point_cells) {
        // named as given: 1e39 is not a float, and would be reported as inf
        if (beyondFloatRange(cell_size) || belowFloatRange(cell_size))
          throw py::value_error("cell_size " + formatNumber(cell_size) +
                                " is outside the single-precision range");
        validateCellSize(static_cast<float>(cell_size));
        GridParams params;
        params.cell_size = static_cast<float>(cell_size);
        parseOrigin(origin, params);
        params.exact_cell_size = cell_size;
        params.threads = threads;
        params.point_cells = point_cells;
        PointsArray p = pointsFromArray(points, "points");
        auto result = std::make_shared<GridResult>();
        {
          py::gil_scoped_release release;
          GridWorkspace workspace;
          buildGrid(p.span, params, workspace, *result);
        }
        return result;
      },
      py::arg("points"), py::arg("cell_size") = 1.0f, py::arg("origin") = "cloud-min",
      py::arg("threads") = 0u, py::kw_only(), py::arg("point_cells") = false, R"doc(
Bin points into cubic cells: per occupied cell its index, count and mean (OccupancyGrid).

Parameters
----------
points : array_like, shape (N, 3) or (N, 4)
    x, y, z (and a fourth column, ignored) in metres. C-contiguous float32 (N, 4) or (N, 3)
    is read in place; any other real dtype or layout is converted to float32 once.
    Points with a NaN/Inf coordinate are skipped and counted.
cell_size : float
    Cell edge in metres, finite and > 0.
origin : {'cloud-min', 'world', 'open3d'} or (x, y, z)
    'cloud-min' (the study's partition): index = floor((p - min) / cell_size);
    'world' (pcl::VoxelGrid's): index = floor(p * (1 / cell_size)) in float32;
    'open3d' (Open3D's voxel_down_sample): index = floor((p - (min - cell_size / 2)) /
    cell_size) in float64, so the cells and means are Open3D's;
    (x, y, z): cell (0, 0, 0) starts at that point, index = floor((p - origin) / cell_size)
    in float64. `Grid.origin` is where cell (0, 0, 0) starts.
threads : int
    0 = all hardware threads. The result does not depend on it.
point_cells : bool
    Also give each point's cell: `Grid.point_cells`, (N,) int64 rows into the cell arrays
    (-1 for a skipped point), as np.unique(..., return_inverse=True) gives.

Returns
-------
Grid
    statistics, and per-cell arrays (views): indices (M, 3) int64, counts (M,) uint64,
    means (M, 3) float64, first_points (M,) uint64.

Raises
------
ValueError
    bad cell size or origin, wrong shape, no rows.
TypeError
    a non-numeric dtype.
CapacityError
    the bounding volume has 2**64 cells or more.
)doc");
}

}  // namespace metricmap::python
