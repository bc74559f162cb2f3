// metricmap.DistanceField: the exact Euclidean distance field (distance/distance_field.h) of a
// LogOddsMap, a map_server map or a point array; the field as a zero-copy numpy view,
// vectorised queries with the GIL released.
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.h"
#include "log_odds_object.h"
#include "metricmap/common/format_number.h"
#include "metricmap/distance/distance_sources.h"
#include "metricmap/distance/distance_volume.h"
#include "metricmap/distance/inflation_costmap.h"
#include "metricmap/io/map_server_reader.h"
#include "metricmap/io/output_set.h"

namespace metricmap::python {
namespace {

/// (N, 3) float64 query points; (N, 2) and (2,)/(3,) accepted (z = 0 for 2D).
/// Query points as x, y, z rows: (N, 3), or (N, 2) for a 2D field (z = 0); a single point may
/// be given as a 1-D array.
std::vector<double> queryXyz(const py::handle& obj, const DistanceField& field) {
  auto a = doublesFromArray(obj, "points");
  if (a.ndim() == 1) a = a.reshape({py::ssize_t(1), a.shape(0)});
  const bool planar = field.dimensions() == 2;
  if (a.ndim() != 2 || (a.shape(1) != 3 && !(planar && a.shape(1) == 2)))
    throw py::value_error(planar ? "points must have shape (N, 3) or (N, 2)"
                                 : "points must have shape (N, 3) for a 3D field");
  const auto n = static_cast<std::size_t>(a.shape(0)), cols = static_cast<std::size_t>(a.shape(1));
  std::vector<double> xyz(3 * n, 0.0);
  const double* d = a.data();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < cols; ++c) {
      const double v = d[cols * i + c];
      if (!std::isfinite(v))
        throw py::value_error("points row " + std::to_string(i) + ": " + formatNumber(v) +
                              " is not a finite number");
      xyz[3 * i + c] = v;
    }
  return xyz;
}

DistanceFieldParams paramsOf(double max_distance, const std::string& unknown, bool signed_distance,
                             bool incremental, unsigned threads) {
  DistanceFieldParams p;
  p.max_distance = max_distance;
  if (unknown != "free" && unknown != "occupied")
    throw py::value_error("unknown must be 'free' or 'occupied', got '" + unknown + "'");
  p.unknown = unknown == "occupied" ? UnknownAs::Occupied : UnknownAs::Free;
  p.signed_distance = signed_distance;
  p.incremental = incremental;
  p.threads = threads;
  return p;
}

py::tuple shapeOf(const DistanceField& f) {
  py::list s;
  for (int a = 0; a < f.dimensions(); ++a) s.append(f.shape()[a]);
  return py::tuple(s);
}

}  // namespace

void initDistance(py::module_& m) {
  py::class_<DistanceField>(m, "DistanceField", R"doc(
Exact Euclidean distance field over a map's box: from each voxel (cell) centre to the nearest
obstacle voxel's centre, clamped at max_distance (see docs/DISTANCE.md).

source: a LogOddsMap (its known voxels' bounds), a map_server YAML path (2D), or an (N, 3)
point array (needs resolution; voxels holding a point are obstacles, the rest of their
bounds free). unknown: 'free' or 'occupied' (then space beyond the box is an obstacle too).
signed: negative inside obstacles. incremental: keep the passes so that update() recomputes
only what a change reaches.
)doc")
      .def(
          py::init([](py::object source, double max_distance, std::optional<double> resolution,
                      const std::string& unknown, bool signed_distance, bool incremental,
                      unsigned threads) {
            const DistanceFieldParams p =
                paramsOf(max_distance, unknown, signed_distance, incremental, threads);
            if (py::isinstance<PyLogOddsMap>(source)) {
              if (resolution) throw py::value_error("resolution applies to point arrays only");
              const PyLogOddsMap& map = source.cast<const PyLogOddsMap&>();
              ObjectGuard guard(map.mutex, "LogOddsMap");
              py::gil_scoped_release release;
              return std::make_unique<DistanceField>(occupancyBoxOf(*map.map, p), p);
            }
            if (py::isinstance<py::str>(source) ||
                py::isinstance(source, py::module_::import("os").attr("PathLike"))) {
              if (resolution) throw py::value_error("resolution applies to point arrays only");
              if (incremental)
                throw py::value_error(
                    "incremental has no effect on a map_server map: a 2D field cannot be updated "
                    "from a 3D log-odds map");
              const std::string path = py::str(py::module_::import("os").attr("fspath")(source));
              py::gil_scoped_release release;
              const Map2D map = loadMapServer(path);
              return std::make_unique<DistanceField>(occupancyBoxOf(map, p), p);
            }
            if (!py::hasattr(source, "__len__") && !py::hasattr(source, "__array__") &&
                !PyObject_CheckBuffer(source.ptr()))
              throw py::type_error(
                  "source must be a LogOddsMap, a map_server YAML path or an (N, 3) point array, "
                  "got " +
                  std::string(py::str(py::type::of(source).attr("__name__"))));
            if (!resolution) throw py::value_error("a point array needs resolution");
            const PointsArray pts = pointsFromArray(source, "points");
            py::gil_scoped_release release;
            return std::make_unique<DistanceField>(
                occupancyBoxOfPoints(pts.span.base, pts.span.stride, pts.span.size, *resolution, p),
                p);
          }),
          py::arg("source"), py::arg("max_distance") = 2.0, py::arg("resolution") = py::none(),
          py::arg("unknown") = "free", py::arg("signed") = false, py::arg("incremental") = false,
          py::arg("threads") = 0)
      .def_property_readonly(
          "field",
          [](py::object self) {
            const DistanceField& f = self.cast<const DistanceField&>();
            std::vector<py::ssize_t> shape, strides;
            py::ssize_t stride = sizeof(float);
            for (int a = f.dimensions() - 1; a >= 0; --a) {
              shape.insert(shape.begin(), static_cast<py::ssize_t>(f.shape()[a]));
              strides.insert(strides.begin(), stride);
              stride *= static_cast<py::ssize_t>(f.shape()[a]);
            }
            return viewOf(f.field().data(), shape, strides, self);
          },
          "The distances (float32, metres, C order, shape (nx, ny[, nz])): a read-only view of "
          "the field, valid while the object lives and until update()")
      .def_property_readonly(
          "states",
          [](py::object self) {
            const DistanceField& f = self.cast<const DistanceField&>();
            std::vector<py::ssize_t> shape, strides;
            py::ssize_t stride = 1;
            for (int a = f.dimensions() - 1; a >= 0; --a) {
              shape.insert(shape.begin(), static_cast<py::ssize_t>(f.shape()[a]));
              strides.insert(strides.begin(), stride);
              stride *= static_cast<py::ssize_t>(f.shape()[a]);
            }
            return viewOf(f.states().data(), shape, strides, self);
          },
          "Voxel states (uint8: UNKNOWN, FREE, OCCUPIED), a read-only view like field")
      .def_property_readonly("shape", &shapeOf)
      .def_property_readonly("dimensions", &DistanceField::dimensions)
      .def_property_readonly("resolution", &DistanceField::resolution)
      .def_property_readonly(
          "origin",
          [](const DistanceField& f) {
            return std::vector<double>(f.origin().data(), f.origin().data() + f.dimensions());
          },
          "Centre of voxel (0, 0[, 0]): voxel (i, j, k) is at origin + (i, j, k) * resolution")
      .def_property_readonly("max_distance",
                             [](const DistanceField& f) { return f.params().max_distance; })
      .def_property_readonly("seconds", &DistanceField::seconds,
                             "Seconds the last transform or update took")
      .def(
          "query",
          [](const DistanceField& f, ArrayLike points) {
            const std::vector<double> xyz = queryXyz(points, f);
            const std::size_t n = xyz.size() / 3;
            py::array_t<double> d(static_cast<py::ssize_t>(n));
            py::array_t<double> g({static_cast<py::ssize_t>(n), py::ssize_t(3)});
            double* dp = d.mutable_data();
            double* gp = g.mutable_data();
            {
              py::gil_scoped_release release;
              f.queryMany(xyz.data(), n, dp, gp);
            }
            return py::make_tuple(d, g);
          },
          py::arg("points"),
          "(distance (N,), gradient (N, 3)) at points (N, 3) or (N, 2): the trilinear "
          "(bilinear) interpolant and its gradient; NaN outside the outer voxel centres")
      .def(
          "is_observed",
          [](const DistanceField& f, ArrayLike points) {
            const std::vector<double> xyz = queryXyz(points, f);
            const std::size_t n = xyz.size() / 3;
            py::array_t<bool> out(static_cast<py::ssize_t>(n));
            bool* o = out.mutable_data();
            py::gil_scoped_release release;
            for (std::size_t i = 0; i < n; ++i)
              o[i] = f.isObserved(Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
            return out;
          },
          py::arg("points"), "Whether the voxel holding each point was observed (N,) bool")
      .def(
          "nearest_obstacle",
          [](const DistanceField& f, ArrayLike points) {
            const std::vector<double> xyz = queryXyz(points, f);
            const std::size_t n = xyz.size() / 3;
            py::array_t<double> pos({static_cast<py::ssize_t>(n), py::ssize_t(3)});
            py::array_t<bool> found(static_cast<py::ssize_t>(n));
            double* p = pos.mutable_data();
            bool* ok = found.mutable_data();
            {
              py::gil_scoped_release release;
              for (std::size_t i = 0; i < n; ++i) {
                Eigen::Vector3d o = Eigen::Vector3d::Constant(std::nan(""));
                ok[i] = f.nearestObstacle(
                    Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), o);
                if (!ok[i]) o.setConstant(std::nan(""));
                for (int a = 0; a < 3; ++a) p[3 * i + a] = o[a];
              }
            }
            return py::make_tuple(pos, found);
          },
          py::arg("points"),
          "(positions (N, 3), found (N,)): the nearest obstacle voxel centre within "
          "max_distance of each point's voxel; NaN where none")
      .def(
          "write_vdb",
          [](const DistanceField& f, const std::filesystem::path& path) {
            try {
              py::gil_scoped_release release;
              OutputSet staged;
              writeVdb(staged.stage(path.string()), vdbVolumeOf(f));
              staged.commit();
            } catch (const std::runtime_error& e) {
              raiseOSError(e);
            }
          },
          py::arg("path"),
          "Write the field as OpenVDB (FloatGrid 'distance', voxel (i, j, k) at origin + (i, j, "
          "k) * resolution, voxels at max_distance inactive; a signed field as a level set), "
          "atomically. OSError when it fails.")
      .def(
          "update",
          [](DistanceField& f, const PyLogOddsMap& map) {
            DistanceUpdateReport r;
            ObjectGuard guard(map.mutex, "LogOddsMap");
            {
              py::gil_scoped_release release;
              r = f.update(*map.map);
            }
            py::dict d;
            d["changed_voxels"] = r.changed_voxels;
            d["observed_voxels"] = r.observed_voxels;
            d["outside_voxels"] = r.outside_voxels;
            d["lines"] = r.lines;
            d["full"] = r.full;
            return d;
          },
          py::arg("map"),
          "Bring the field up to date with the LogOddsMap it was built from (same box); equals "
          "a field computed anew. Views of field taken before stay valid and see the new values")
      .def(
          "costmap",
          [](const DistanceField& f, double inscribed_radius, double inflation_radius,
             double cost_scaling_factor) {
            InflationParams ip;
            ip.inscribed_radius = inscribed_radius;
            ip.inflation_radius = inflation_radius;
            ip.cost_scaling_factor = cost_scaling_factor;
            MapServerImage im;
            {
              py::gil_scoped_release release;
              im = inflationCostmap(f, ip);
            }
            return arrayFrom(im.pixels, {im.height, im.width});
          },
          py::arg("inscribed_radius") = 0.1, py::arg("inflation_radius") = 0.55,
          py::arg("cost_scaling_factor") = 10.0,
          "nav2 inflation costmap (uint8 (H, W), row 0 at the top) of a 2D unsigned field with "
          "max_distance >= the inflation radius plus two cells");
}

}  // namespace metricmap::python
