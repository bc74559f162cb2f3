// metricmap.LogOddsMap: the probabilistic 3D voxel map (occupancy/log_odds_map.h) with
// OctoMap-python's shape: insert_point_cloud(points, origin, max_range), queries, .bt/.ot.
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.h"
#include "log_odds_object.h"
#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "metricmap/occupancy/octomap_io.h"
#include "metricmap/occupancy/octomap_quiet.h"
#include "object_lock.h"

namespace metricmap::python {

namespace {

CArray<double> queryPoints(const py::handle& obj) {
  auto a = doublesFromArray(pointsOf(obj), "points");
  if (a.ndim() == 1 && a.shape(0) == 3) a = a.reshape({py::ssize_t(1), py::ssize_t(3)});
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error("points must have shape (N, 3) or (3,)");
  return a;
}

py::array_t<double> centres(const LogOddsMap& map, bool occupied) {
  std::vector<Eigen::Vector3d> c = voxelCenters(map, occupied);
  py::array_t<double> a({py::ssize_t(c.size()), py::ssize_t(3)});
  double* d = a.mutable_data();
  for (std::size_t i = 0; i < c.size(); ++i)
    for (int k = 0; k < 3; ++k) d[3 * i + k] = c[i][k];
  return a;
}

/// The map's state for pickle: (resolution, prob_hit, prob_miss, clamp_min, clamp_max,
/// occupancy_threshold, max_range), keys (K, 3) int64, log-odds (K,) float32.
py::tuple mapState(const PyLogOddsMap& self) {
  ObjectGuard guard(self.mutex, "LogOddsMap");
  const LogOddsParams& p = self.map->params();
  std::vector<std::int64_t> keys;
  std::vector<float> values;
  keys.reserve(3 * self.map->knownVoxels());
  values.reserve(self.map->knownVoxels());
  self.map->forEachKnown([&](const VoxelKey& k, float l) {
    keys.insert(keys.end(), {k.x, k.y, k.z});
    values.push_back(l);
  });
  const py::ssize_t n = static_cast<py::ssize_t>(values.size());
  return py::make_tuple(py::make_tuple(p.resolution, p.prob_hit, p.prob_miss, p.clamp_min,
                                       p.clamp_max, p.occupancy_threshold, p.max_range),
                        arrayFrom(keys, {n, 3}), arrayFrom(values, {n}));
}

std::unique_ptr<PyLogOddsMap> mapFromState(const py::tuple& t) {
  if (t.size() != 3) throw py::value_error("LogOddsMap: not a pickled map");
  const auto q = t[0].cast<std::vector<double>>();
  if (q.size() != 7) throw py::value_error("LogOddsMap: not a pickled map");
  const LogOddsParams p{q[0], q[1], q[2], q[3], q[4], q[5], q[6]};
  auto keys = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>(t[1]);
  auto values = py::array_t<float, py::array::c_style | py::array::forcecast>(t[2]);
  if (keys.ndim() != 2 || keys.shape(1) != 3 || values.ndim() != 1 ||
      values.shape(0) != keys.shape(0))
    throw py::value_error("LogOddsMap: not a pickled map");
  auto out = std::make_unique<PyLogOddsMap>();
  out->map = std::make_unique<LogOddsMap>(p);
  for (py::ssize_t k = 0; k < values.shape(0); ++k)
    out->map->setLogOdds(VoxelKey{keys.at(k, 0), keys.at(k, 1), keys.at(k, 2)}, values.at(k));
  return out;
}

/// Same parameters and the same log-odds in the same voxels.
bool sameMap(const LogOddsMap& a, const LogOddsMap& b) {
  const LogOddsParams &p = a.params(), &q = b.params();
  if (p.resolution != q.resolution || p.prob_hit != q.prob_hit || p.prob_miss != q.prob_miss ||
      p.clamp_min != q.clamp_min || p.clamp_max != q.clamp_max ||
      p.occupancy_threshold != q.occupancy_threshold || p.max_range != q.max_range ||
      a.knownVoxels() != b.knownVoxels())
    return false;
  bool same = true;
  a.forEachKnown([&](const VoxelKey& k, float l) {
    const std::optional<float> m = b.logOdds(k);
    same = same && m && *m == l;
  });
  return same;
}

}  // namespace

void initLogOdds(py::module_& m) {
  m.attr("UNKNOWN") = 0;
  m.attr("FREE") = 1;
  m.attr("OCCUPIED") = 2;
  py::class_<PyLogOddsMap>(m, "LogOddsMap", R"doc(
Probabilistic 3D voxel map (OctoMap's sensor model and defaults; world-aligned voxels
floor(p / resolution)), updated by casting every beam of a scan from the sensor origin.
)doc")
      .def(py::init([](double resolution, double prob_hit, double prob_miss, double clamp_min,
                       double clamp_max, double occupancy_threshold) {
             LogOddsParams p;
             p.resolution = resolution;
             p.prob_hit = prob_hit;
             p.prob_miss = prob_miss;
             p.clamp_min = clamp_min;
             p.clamp_max = clamp_max;
             p.occupancy_threshold = occupancy_threshold;
             return PyLogOddsMap{std::make_unique<LogOddsMap>(p)};
           }),
           py::arg("resolution") = 0.1, py::arg("prob_hit") = 0.7, py::arg("prob_miss") = 0.4,
           py::arg("clamp_min") = 0.1192, py::arg("clamp_max") = 0.971,
           py::arg("occupancy_threshold") = 0.5, R"doc(
Parameters
----------
resolution : float
    Voxel edge, metres (> 0).
prob_hit, prob_miss : float
    P(occupied | hit) and P(occupied | miss), in (0, 1).
clamp_min, clamp_max : float
    Clamping bounds, as probabilities.
occupancy_threshold : float
    Occupied iff probability >= this.
)doc")
      .def_static(
          "read",
          [](const std::filesystem::path& path, double prob_hit, double prob_miss, double clamp_min,
             double clamp_max, double occupancy_threshold) {
            LogOddsParams p;
            p.prob_hit = prob_hit;
            p.prob_miss = prob_miss;
            p.clamp_min = clamp_min;
            p.clamp_max = clamp_max;
            p.occupancy_threshold = occupancy_threshold;
            py::gil_scoped_release release;
            return PyLogOddsMap{std::make_unique<LogOddsMap>(readOctomapQuietly(path.string(), p))};
          },
          py::arg("path"), py::arg("prob_hit") = 0.7, py::arg("prob_miss") = 0.4,
          py::arg("clamp_min") = 0.1192, py::arg("clamp_max") = 0.971,
          py::arg("occupancy_threshold") = 0.5,
          "Read an OctoMap .bt or .ot file (the file gives the resolution; pruned leaves are "
          "expanded to voxels). Raises InputError (an OSError) for a bad file.")
      .def(
          "insert_point_cloud",
          [](PyLogOddsMap& self, ArrayLike points, ArrayLike origin, double max_range) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            PointsArray p = pointsFromArray(points, "points", true);
            const Eigen::Vector3d o = vector3From(origin, "origin");
            for (int i = 0; i < 3; ++i)  // named as given: 1e39 is not a float (it would read inf)
              if (beyondFloatRange(o[i]))
                throw py::value_error("origin[" + std::to_string(i) + "] " + formatNumber(o[i]) +
                                      " is outside the single-precision range");
            if (std::isnan(max_range)) throw py::value_error("max_range must not be NaN");
            self.useMaxRange(max_range);
            ScanInsertReport r;
            {
              py::gil_scoped_release release;
              r = self.map->insertRaw(p.span.base, p.span.stride, p.span.size, o.cast<float>(),
                                      nullptr);
            }
            py::dict d;
            d["points"] = r.points;
            d["non_finite"] = r.non_finite;
            d["beams"] = r.beams;
            d["beams_cut"] = r.beams_cut;
            d["hit_voxels"] = r.hit_voxels;
            d["miss_voxels"] = r.miss_voxels;
            return d;
          },
          py::arg("points"), py::arg("origin"), py::arg("max_range") = -1.0, R"doc(
Cast every beam from `origin` to each point (world frame), as OctoMap's insertPointCloud.

Parameters
----------
points : array_like, shape (N, 3) or (N, 4)
    Beam endpoints, metres, world frame; C-contiguous float32 is read in place.
    NaN/Inf points are skipped and counted.
origin : array_like, shape (3,)
    Sensor position, metres.
max_range : float
    Beams longer than this are cut there and mark no hit; <= 0 (default -1): no limit.

Returns
-------
dict
    points, non_finite, beams, beams_cut, hit_voxels, miss_voxels.

Raises
------
CapacityError
    a point or the origin outside the key space (the map is then unchanged).
)doc")
      .def(
          "probability",
          [](const PyLogOddsMap& self, ArrayLike points) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            auto a = queryPoints(points);
            const std::size_t n = static_cast<std::size_t>(a.shape(0));
            py::array_t<double> out(static_cast<py::ssize_t>(n));
            const double* q = a.data();
            double* o = out.mutable_data();
            for (std::size_t i = 0; i < n; ++i) {
              const Eigen::Vector3d p(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
              o[i] = p.allFinite() ? self.map->probability(p)
                                   : std::numeric_limits<double>::quiet_NaN();
            }
            return out;
          },
          py::arg("points"),
          "(N,) float64: occupancy probability of the voxel holding each point (0.5 unknown, "
          "NaN for a non-finite point).")
      .def(
          "log_odds",
          [](const PyLogOddsMap& self, ArrayLike points) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            auto a = queryPoints(points);
            const std::size_t n = static_cast<std::size_t>(a.shape(0));
            py::array_t<float> out(static_cast<py::ssize_t>(n));
            const double* q = a.data();
            float* o = out.mutable_data();
            for (std::size_t i = 0; i < n; ++i) {
              const Eigen::Vector3d p(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
              std::optional<float> l;
              if (p.allFinite()) l = self.map->logOdds(self.map->keyOf(p));
              o[i] = l ? *l : std::numeric_limits<float>::quiet_NaN();
            }
            return out;
          },
          py::arg("points"), "(N,) float32: log-odds of each point's voxel, NaN where unknown.")
      .def(
          "states",
          [](const PyLogOddsMap& self, ArrayLike points) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            auto a = queryPoints(points);
            const std::size_t n = static_cast<std::size_t>(a.shape(0));
            py::array_t<std::int8_t> out(static_cast<py::ssize_t>(n));
            const double* q = a.data();
            std::int8_t* o = out.mutable_data();
            for (std::size_t i = 0; i < n; ++i) {
              const Eigen::Vector3d p(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
              const VoxelState s = p.allFinite() ? self.map->state(p) : VoxelState::Unknown;
              o[i] = s == VoxelState::Occupied ? 2 : (s == VoxelState::Free ? 1 : 0);
            }
            return out;
          },
          py::arg("points"),
          "(N,) int8: UNKNOWN (0), FREE (1) or OCCUPIED (2) for each point's voxel.")
      .def(
          "voxels",
          [](const PyLogOddsMap& self) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            const std::size_t n = self.map->knownVoxels();
            py::array_t<std::int64_t> keys({py::ssize_t(n), py::ssize_t(3)});
            py::array_t<float> values(static_cast<py::ssize_t>(n));
            std::int64_t* k = keys.mutable_data();
            float* v = values.mutable_data();
            std::size_t i = 0;
            self.map->forEachKnown([&](const VoxelKey& key, float l) {
              if (i >= n) return;
              k[3 * i] = key.x;
              k[3 * i + 1] = key.y;
              k[3 * i + 2] = key.z;
              v[i++] = l;
            });
            return py::make_tuple(keys, values);
          },
          "(keys (K, 3) int64, log_odds (K,) float32) of every known voxel; voxel k spans "
          "[k * resolution, (k + 1) * resolution).")
      .def(
          "extract_point_cloud",
          [](const PyLogOddsMap& self) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            return py::make_tuple(centres(*self.map, true), centres(*self.map, false));
          },
          "(occupied (K, 3), free (F, 3)) float64 voxel centres, as octomap-python's "
          "extractPointCloud.")
      .def(
          "write",
          [](const PyLogOddsMap& self, const std::filesystem::path& path) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            try {
              py::gil_scoped_release release;
              writeOctomapQuietly(*self.map, path.string());
            } catch (const std::invalid_argument&) {
              throw;
            } catch (const CapacityError&) {
              throw;
            } catch (const std::runtime_error& e) {
              raiseOSError(e);
            }
          },
          py::arg("path"),
          "Write an OctoMap file: .bt (maximum likelihood) or .ot (log-odds), by extension. "
          "Raises OSError when it cannot be written, ValueError for another extension.")
      .def(
          "project_band",
          [](const PyLogOddsMap& self, double z_min, double z_max) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            const TrinaryMap t = projectBand(*self.map, z_min, z_max);
            py::array_t<std::uint8_t> cells({py::ssize_t(t.height), py::ssize_t(t.width)});
            if (!t.cells.empty()) std::copy(t.cells.begin(), t.cells.end(), cells.mutable_data());
            py::dict info;
            info["resolution"] = t.resolution;
            info["origin"] = py::make_tuple(t.origin_x, t.origin_y);
            info["occupied"] = t.occupied;
            info["free"] = t.free;
            return py::make_tuple(cells, info);
          },
          py::arg("z_min"), py::arg("z_max"), R"doc(
Project the voxels whose centre z lies in [z_min, z_max] onto the xy plane (the CLI's --band).

Returns
-------
cells : numpy.ndarray, shape (H, W), uint8
    map_server's trinary values: 0 occupied, 254 free, 205 unknown; row 0 holds the largest y.
info : dict
    resolution (m), origin (x, y of the lower-left corner of the lower-left pixel), occupied,
    free (cell counts).

Raises
------
ValueError
    a band that is not finite with z_min <= z_max, or no known voxel in it.
)doc")
      .def(
          "merge",
          [](PyLogOddsMap& self, const PyLogOddsMap& other) {
            PairGuard guard(self.mutex, other.mutex, "LogOddsMap");
            self.map->merge(*other.map);
          },
          py::arg("other"), "Add the log-odds of every voxel of `other` (clamped).")
      .def(
          "clear",
          [](PyLogOddsMap& self) {
            ObjectGuard guard(self.mutex, "LogOddsMap");
            self.map->clear();
          },
          "Forget every voxel.")
      .def_property_readonly("resolution",
                             [](const PyLogOddsMap& self) {
                               ObjectGuard guard(self.mutex, "LogOddsMap");
                               return self.map->resolution();
                             })
      .def_property_readonly("known_voxels",
                             [](const PyLogOddsMap& self) {
                               ObjectGuard guard(self.mutex, "LogOddsMap");
                               return self.map->knownVoxels();
                             })
      .def_property_readonly("occupied_voxels",
                             [](const PyLogOddsMap& self) {
                               ObjectGuard guard(self.mutex, "LogOddsMap");
                               return self.map->occupiedVoxels();
                             })
      .def_property_readonly("free_voxels",
                             [](const PyLogOddsMap& self) {
                               ObjectGuard guard(self.mutex, "LogOddsMap");
                               return self.map->freeVoxels();
                             })
      .def(py::pickle(&mapState, &mapFromState))
      .def(
          "__eq__",
          [](const PyLogOddsMap& self, const py::object& other) {
            if (!py::isinstance<PyLogOddsMap>(other)) return false;
            const PyLogOddsMap& o = other.cast<const PyLogOddsMap&>();
            PairGuard guard(self.mutex, o.mutex, "LogOddsMap");
            return sameMap(*self.map, *o.map);
          },
          py::is_operator())
      .def("__repr__", [](const PyLogOddsMap& self) {
        ObjectGuard guard(self.mutex, "LogOddsMap");
        return "<metricmap.LogOddsMap resolution " + formatNumber(self.map->resolution()) + ", " +
               std::to_string(self.map->knownVoxels()) + " known voxels>";
      });
}

}  // namespace metricmap::python
