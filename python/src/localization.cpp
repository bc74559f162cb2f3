// metricmap.Map2D / read_map / Localizer2D / run_localize2d: 2D localisation in a saved map
// (localization/localizer_2d.h, io/map_server_reader.h).
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "metricmap/common/map_2d.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/map_server_reader.h"
#include "metricmap/localization/localize_2d_run.h"
#include "metricmap/localization/localizer_2d.h"
#include "metricmap/localization/localizer_2d_parameters.h"
#include "object_lock.h"
#include "parameter_list.h"
#include "poses.h"
#include "progress.h"
#include "sequence.h"

namespace metricmap::python {

namespace {

struct PyLocalizer {
  std::unique_ptr<Localizer2D> localizer;
  mutable ObjectMutex mutex;
};

/// A finished run_localize2d: one row per scan given.
struct PyLocalizeRun {
  std::vector<Localization2D> results;
  std::vector<double> stamps;
  std::vector<std::size_t> frames;
  Localizer2DStats stats;
};

std::string pathOf(const py::handle& obj) {
  return py::str(py::module_::import("os").attr("fspath")(obj));
}

/// A Map2D object, or a map_server YAML path loaded (the GIL released while reading).
Map2D mapFrom(const py::handle& obj) {
  if (py::isinstance<Map2D>(obj)) return obj.cast<const Map2D&>();
  if (!py::isinstance<py::str>(obj) &&
      !py::isinstance(obj, py::module_::import("os").attr("PathLike")))
    throw py::type_error("map must be a Map2D or the path of a map_server YAML");
  const std::string path = pathOf(obj);
  py::gil_scoped_release release;
  return loadMapServer(path);
}

/// Parameters by name (localizer2DParameterNames) onto the defaults, then checked as a whole.
Localizer2DConfig configFrom(const std::optional<py::dict>& parameters) {
  Localizer2DConfig c;
  if (parameters) {
    for (const auto& [key, value] : *parameters) {
      if (!py::isinstance<py::str>(key)) throw py::type_error("parameter names must be str");
      if (py::isinstance<py::bool_>(value) ||
          !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)))
        throw py::type_error("parameter " + key.cast<std::string>() + " must be a number, got " +
                             std::string(py::str(value.get_type().attr("__name__"))));
      setLocalizer2DParameter(c, key.cast<std::string>(), py::str(value).cast<std::string>());
    }
  }
  validateLocalizer2DConfig(c);
  return c;
}

py::object poseOrNone(const Localization2D& r) {
  if (!r.localised()) return py::none();
  py::array_t<double> a(3);
  double* p = a.mutable_data();
  p[0] = r.pose.x, p[1] = r.pose.y, p[2] = r.pose.theta;
  return std::move(a);
}

py::dict statsDict(const Localizer2DStats& s) {
  py::dict d;
  d["scans"] = s.scans;
  d["localised"] = s.localised;
  d["global_searches"] = s.global_searches;
  d["fixes"] = s.fixes;
  d["ambiguous"] = s.ambiguous;
  d["losses"] = s.losses;
  d["candidates"] = s.candidates;
  d["first_fix"] = s.first_fix ? py::cast(*s.first_fix) : py::none();
  d["setup_seconds"] = s.setup_seconds;
  d["global_seconds"] = s.global_seconds;
  d["track_seconds"] = s.track_seconds;
  return d;
}

void initMap2D(py::module_& m) {
  py::class_<Map2D>(m, "Map2D", R"doc(
A 2D occupancy map (map_server's model): cells of `resolution` m, the lower-left corner at
`origin` (x, y, yaw). `cells` is (height, width) int8 in ROS OccupancyGrid values: -1 unknown,
0 free, 100 occupied; row 0 is the row at the origin (the lowest y), as nav_msgs/OccupancyGrid.
)doc")
      .def_property_readonly(
          "cells",
          [](const Map2D& map) {
            py::array_t<std::int8_t> a({py::ssize_t(map.height), py::ssize_t(map.width)});
            if (!map.cells.empty()) std::copy(map.cells.begin(), map.cells.end(), a.mutable_data());
            return a;
          },
          "(height, width) int8: -1 unknown, 0 free, 100 occupied; row 0 at the origin (a copy)")
      .def_property_readonly(
          "resolution", [](const Map2D& map) { return map.resolution; }, "Cell edge (m).")
      .def_property_readonly(
          "origin",
          [](const Map2D& map) {
            return py::make_tuple(map.origin.x, map.origin.y, map.origin.theta);
          },
          "(x, y, yaw) of the lower-left corner (m, m, rad).")
      .def_property_readonly(
          "width", [](const Map2D& map) { return map.width; }, "Cells in x.")
      .def_property_readonly(
          "height", [](const Map2D& map) { return map.height; }, "Cells in y.")
      .def(py::pickle(
          [](const Map2D& map) {
            return py::make_tuple(
                map.width, map.height, map.resolution, map.origin.x, map.origin.y, map.origin.theta,
                py::bytes(reinterpret_cast<const char*>(map.cells.data()), map.cells.size()));
          },
          [](const py::tuple& t) {
            if (t.size() != 7) throw py::value_error("Map2D: not a pickled map");
            Map2D map;
            map.width = t[0].cast<int>();
            map.height = t[1].cast<int>();
            map.resolution = t[2].cast<double>();
            map.origin = Pose2D{t[3].cast<double>(), t[4].cast<double>(), t[5].cast<double>()};
            const std::string cells = t[6].cast<std::string>();
            if (map.width < 0 || map.height < 0 ||
                cells.size() != static_cast<std::size_t>(map.width) * map.height)
              throw py::value_error("Map2D: not a pickled map");
            map.cells.assign(cells.begin(), cells.end());
            return map;
          }))
      .def(
          "__eq__",
          [](const Map2D& a, const py::object& other) {
            if (!py::isinstance<Map2D>(other)) return false;
            const Map2D& b = other.cast<const Map2D&>();
            return a.width == b.width && a.height == b.height && a.resolution == b.resolution &&
                   a.origin.x == b.origin.x && a.origin.y == b.origin.y &&
                   a.origin.theta == b.origin.theta && a.cells == b.cells;
          },
          py::is_operator())
      .def("__repr__", [](const Map2D& map) {
        return "Map2D(" + std::to_string(map.width) + " x " + std::to_string(map.height) +
               " cells of " + py::repr(py::float_(map.resolution)).cast<std::string>() + " m)";
      });

  m.def(
      "read_map", [](const py::object& path) { return mapFrom(path); }, py::arg("path"), R"doc(
Read a map_server map: the YAML (image, resolution, origin, negate, occupied_thresh,
free_thresh, mode trinary/scale/raw as map_server reads them) and the PGM it names.

Raises
------
InputError
    a missing, special or malformed file (one line naming it).
CapacityError
    an image beyond the memory budget.
)doc");
}

void initLocalizer(py::module_& m) {
  py::class_<Localization2D>(m, "Localization2D", "What one scan gave (Localizer2D.localize).")
      .def_property_readonly(
          "status", [](const Localization2D& r) { return std::string(statusName(r.status)); },
          "'not_found', 'ambiguous', 'waiting', 'fixed', 'tracked', 'weak' or 'lost'.")
      .def_property_readonly("localised", &Localization2D::localised,
                             "True for 'fixed' and 'tracked'.")
      .def_property_readonly("pose", &poseOrNone,
                             "(3,) x, y, yaw in the map's frame, None unless localised.")
      .def_readonly("score", &Localization2D::score, "Mean probability of the scan's cells.")
      .def_readonly("margin", &Localization2D::margin,
                    "Global search: the best's score minus the best distinct pose's.")
      .def("__repr__", [](const Localization2D& r) {
        return std::string("Localization2D(") + statusName(r.status) +
               ", score=" + py::repr(py::float_(r.score)).cast<std::string>() + ")";
      });

  py::class_<PyLocalizer>(m, "Localizer2D", R"doc(
Find and track a laser robot in a fixed 2D map (see docs/LOCALIZATION.md): a global
branch-and-bound search over the whole map and every heading until a fix is accepted (score and
margin over the best distinct pose), then tracking from the motion prediction; a robot lost
for `lost_after_weak_scans` scans is searched for again. Calls on one object are serialised
(threads wait for each other).
)doc")
      .def(py::init([](const py::object& map, std::optional<py::dict> parameters,
                       ArrayLike sensor_to_base) {
             const Localizer2DConfig c = configFrom(parameters);
             const Pose2D sensor = pose2dFrom(sensor_to_base, "sensor_to_base");
             const Map2D loaded = mapFrom(map);
             auto p = std::make_unique<PyLocalizer>();
             py::gil_scoped_release release;
             p->localizer = std::make_unique<Localizer2D>(loaded, c, sensor);
             return p;
           }),
           py::arg("map"), py::arg("parameters") = py::none(),
           py::arg("sensor_to_base") = py::make_tuple(0.0, 0.0, 0.0), R"doc(
Parameters
----------
map : Map2D or str or os.PathLike
    A map, or the path of a map_server YAML.
parameters : dict, optional
    Localisation parameters by name (``localize2d_parameters()``; docs/LOCALIZATION.md).
sensor_to_base : array_like
    The laser on the robot: (x, y, theta) in m and rad, or a (4, 4) transform.

Raises
------
ValueError
    an unknown parameter or a value out of its range, an empty map.
)doc")
      .def(
          "set_initial_pose",
          [](PyLocalizer& p, ArrayLike pose) {
            ObjectGuard guard(p.mutex, "Localizer2D");
            p.localizer->setInitialPose(pose2dFrom(pose, "pose"));
          },
          py::arg("pose"),
          "Search the next scan around (x, y, yaw) in the map's frame. ValueError when not "
          "finite, outside the map, or a yaw beyond 1e6 rad.")
      .def(
          "localize",
          [](PyLocalizer& p, ArrayLike angles, ArrayLike ranges,
             std::optional<ArrayLike> odometry) {
            ObjectGuard guard(p.mutex, "Localizer2D");
            LaserScan scan;
            scan.angles = beamVector(angles, "angles");
            scan.ranges = beamVector(ranges, "ranges");
            if (scan.angles.empty()) throw py::value_error("the scan has no beams");
            std::optional<Pose2D> odo;
            if (odometry) odo = pose2dFrom(*odometry, "odometry");
            py::gil_scoped_release release;
            return p.localizer->localize(scan, odo);
          },
          py::arg("angles"), py::arg("ranges"), py::kw_only(), py::arg("odometry") = py::none(),
          R"doc(
Localise the next scan: beams as ``Scan.laser`` gives them (angles, ranges; NaN ranges are
skipped), with the robot's raw odometry pose (x, y, theta) when known.

Raises
------
ValueError
    angles and ranges of different lengths, an empty scan, non-finite odometry.
)doc")
      .def_property_readonly(
          "status",
          [](const PyLocalizer& p) {
            ObjectGuard guard(p.mutex, "Localizer2D");
            return std::string(statusName(p.localizer->status()));
          },
          "The last scan's status ('not_found' before any).")
      .def_property_readonly(
          "stats",
          [](const PyLocalizer& p) {
            ObjectGuard guard(p.mutex, "Localizer2D");
            return statsDict(p.localizer->stats());
          },
          "Counts (scans, localised, global_searches, fixes, ambiguous, losses, candidates, "
          "first_fix) and seconds per phase.");

  m.def(
      "localize2d_parameters", [] { return parameterList(localizer2DParameterSchema()); },
      "list[dict]: every Localizer2D parameter as the library declares it (name, kind, unit, "
      "rule, min, max, min_open, max_open, default, doc).");

  py::class_<PyLocalizeRun>(m, "LocalizationRun", "A finished run_localize2d: one row per scan.")
      .def_property_readonly(
          "poses",
          [](const PyLocalizeRun& r) {
            py::array_t<double> a({py::ssize_t(r.results.size()), py::ssize_t(3)});
            double* p = a.mutable_data();
            for (const Localization2D& l : r.results) {
              const double nan = std::numeric_limits<double>::quiet_NaN();
              *p++ = l.localised() ? l.pose.x : nan;
              *p++ = l.localised() ? l.pose.y : nan;
              *p++ = l.localised() ? l.pose.theta : nan;
            }
            return a;
          },
          "(N, 3) x, y, yaw in the map's frame; NaN rows where the scan was not localised.")
      .def_property_readonly(
          "localised",
          [](const PyLocalizeRun& r) {
            py::array_t<bool> a(py::ssize_t(r.results.size()));
            for (std::size_t k = 0; k < r.results.size(); ++k)
              a.mutable_data()[k] = r.results[k].localised();
            return a;
          },
          "(N,) bool.")
      .def_property_readonly(
          "status",
          [](const PyLocalizeRun& r) {
            std::vector<std::string> s;
            for (const Localization2D& l : r.results) s.emplace_back(statusName(l.status));
            return s;
          },
          "Each scan's status.")
      .def_property_readonly(
          "scores",
          [](const PyLocalizeRun& r) {
            std::vector<double> s;
            for (const Localization2D& l : r.results) s.push_back(l.score);
            return doublesArray(s);
          },
          "(N,) each scan's score.")
      .def_property_readonly(
          "stamps", [](const PyLocalizeRun& r) { return doublesArray(r.stamps); },
          "(N,) each scan's stamp (NaN where it has none).")
      .def_property_readonly(
          "frames",
          [](const PyLocalizeRun& r) {
            py::array_t<std::int64_t> a(py::ssize_t(r.frames.size()));
            for (std::size_t k = 0; k < r.frames.size(); ++k)
              a.mutable_data()[k] = static_cast<std::int64_t>(r.frames[k]);
            return a;
          },
          "(N,) the source's scan indices.")
      .def_property_readonly(
          "stats", [](const PyLocalizeRun& r) { return statsDict(r.stats); },
          "As Localizer2D.stats.");

  m.def(
      "run_localize2d",
      [](py::object source, const py::object& map, py::object frames,
         std::optional<ArrayLike> initial_pose, std::optional<py::dict> parameters,
         py::object progress) {
        ProgressWatch watch(progress);
        py::object holder;
        PySource& s = sourceFrom(source, holder);
        const SourceInfo& info = s.source->info();
        if (!info.planar)
          throw InputError(info.path +
                           ": localisation needs 2D laser scans (a CARMEN log); "
                           "this is a " +
                           info.kind + " source of 3D scans");
        const std::vector<std::size_t> f = selectedFrames(frames, s.source->size());
        const Localizer2DConfig c = configFrom(parameters);
        const Map2D loaded = mapFrom(map);
        std::optional<Pose2D> initial;
        if (initial_pose) {
          initial = pose2dFrom(*initial_pose, "initial_pose");
          validateInitialPose(loaded, *initial);
        }
        auto r = std::make_unique<PyLocalizeRun>();
        ObjectGuard guard(s.mutex, "ScanSource");
        py::gil_scoped_release release;
        Localize2DRun run = runLocalize2D(*s.source, f, loaded, c, initial,
                                          [&watch](std::size_t done, std::size_t total,
                                                   const Localizer2D&) { watch(done, total); });
        r->results = std::move(run.results);
        r->stamps = std::move(run.stamps);
        r->frames = f;
        r->stats = run.localizer->stats();
        return r;
      },
      py::arg("source"), py::arg("map"), py::arg("frames") = py::none(), py::kw_only(),
      py::arg("initial_pose") = py::none(), py::arg("parameters") = py::none(),
      py::arg("progress") = py::none(), R"doc(
Localise the scans of a planar source (a CARMEN log) in a map, as `metricmap localize` does:
the source's laser offset as sensor_to_base, each scan's beams and raw odometry.

Parameters
----------
source : ScanSource or str or os.PathLike
map : Map2D or str or os.PathLike
    A map, or the path of a map_server YAML.
frames : iterable of int, optional
    Strictly increasing scan indices (default: all; an empty selection is refused).
initial_pose : array_like, optional, keyword-only
    (x, y, yaw) in the map's frame: searched around it instead of the whole map.
parameters : dict, optional, keyword-only
    As Localizer2D.
progress : callable(done, total), optional, keyword-only
    Called at most every 20 ms and after the last scan; Ctrl-C stops the run.

Returns
-------
LocalizationRun

Raises
------
InputError
    a source of 3D scans, a scan without beams, an unreadable map.
ValueError
    bad frames, parameters or initial pose (outside the map, yaw beyond 1e6 rad).
)doc");
}

}  // namespace

void initLocalization(py::module_& m) {
  initMap2D(m);
  initLocalizer(m);
}

}  // namespace metricmap::python
