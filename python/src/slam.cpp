// metricmap.Slam2D / Slam2DConfig / run_slam2d: the 2D laser SLAM (slam/slam_2d.h).
#include <cmath>
#include <deque>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.h"
#include "declared_config.h"
#include "metricmap/exceptions.h"
#include "metricmap/slam/slam_2d.h"
#include "metricmap/slam/slam_2d_parameters.h"
#include "metricmap/slam/slam_2d_run.h"
#include "object_lock.h"
#include "parameter_list.h"
#include "posegraph.h"
#include "poses.h"
#include "progress.h"
#include "sequence.h"
#include "slam_state.h"

namespace metricmap::python {

namespace {

py::dict mapDict(const LogOddsGrid2D& g) {
  py::dict d;
  py::array_t<float> a({py::ssize_t(g.height()), py::ssize_t(g.width())});
  if (g.width() * g.height() > 0)
    std::copy(g.data(), g.data() + g.width() * g.height(), a.mutable_data());
  d["log_odds"] = a;
  d["min_i"] = g.minI();
  d["min_j"] = g.minJ();
  d["resolution"] = g.params().resolution;
  d["occupied_cells"] = g.occupiedCells();
  d["known_cells"] = g.knownCells();
  return d;
}

/// Planar poses beyond this (m) are refused: no map reaches that far (LogOddsGrid2D keeps
/// +-2^30 cells), and the SLAM's cell arithmetic on such values would overflow.
constexpr double kMaxPlanarCoordinate = 1e9;

Pose2D boundedPose(const py::handle& obj, const char* name) {
  const Pose2D p = pose2dFrom(obj, name);
  if (std::abs(p.x) > kMaxPlanarCoordinate || std::abs(p.y) > kMaxPlanarCoordinate ||
      std::abs(p.theta) > kMaxPlanarCoordinate)
    throw py::value_error(std::string(name) + ": a coordinate beyond 1e9 m (or rad)");
  return p;
}

std::unique_ptr<PySlam> makeSlam(const std::optional<Slam2DConfig>& config,
                                 const Pose2D& sensor_to_base) {
  auto p = std::make_unique<PySlam>();
  p->slam = std::make_unique<Slam2D>(config ? *config : Slam2DConfig{}, sensor_to_base);
  return p;
}

/// The attribute names of Slam2DConfig, in declaration order (pickle, ==, repr).
std::vector<std::string>& configFields() {
  static std::vector<std::string> names;
  return names;
}

/// One property per declared parameter (slam/slam_2d_parameters.h): names, kinds, docs and
/// ranges all come from the library's declaration.
void declaredFields(py::class_<Slam2DConfig>& c) {
  for (const ParameterSpec& spec : slam2DParameterSchema()) configFields().push_back(spec.name);
  bindDeclaredFields(c, slam2DParameterSchema(), &slam2DParameterValue, &setSlam2DParameterValue);
}

/// `f` of the finished map, or of the map so far of a running SLAM (built now, without the GIL).
template <typename F>
auto withMap(const PySlam& p, F&& f) {
  if (p.finished()) return f(*p.result->map);
  std::optional<LogOddsGrid2D> live;
  {
    py::gil_scoped_release release;
    live.emplace(p.slam->currentMap());
  }
  return f(*live);
}

}  // namespace

void initSlam(py::module_& m) {
  py::class_<Slam2DConfig> c(m, "Slam2DConfig", R"doc(
Parameters of :class:`Slam2D` (slam/slam_2d_config.h), one attribute each, with Cartographer's
2D defaults; ``Slam2DConfig(max_range=20.0, ...)`` sets attributes by name. Values are checked
when a :class:`Slam2D` is made (ValueError naming the first bad one). The final map's
parameters are the ``map_*`` attributes.
)doc");
  bindKeywordConstructor(c, "Slam2DConfig");
  declaredFields(c);
  m.def(
      "slam2d_parameters", [] { return parameterList(slam2DParameterSchema()); },
      "list[dict]: every Slam2DConfig parameter as the library declares it (name, kind, unit, "
      "rule, min, max, min_open, max_open, default, doc).");
  c.def(
      "validate", [](const Slam2DConfig& s) { validateSlam2DConfig(s); },
      "Raise ValueError naming the first value out of its range.");
  c.def(py::pickle(
      [](const py::object& self) {
        py::dict d;
        for (const std::string& name : configFields()) d[name.c_str()] = self.attr(name.c_str());
        return d;
      },
      [](const py::dict& d) {
        Slam2DConfig config;
        py::object view = py::cast(&config, py::return_value_policy::reference);
        for (auto item : d) view.attr(item.first) = item.second;
        return config;
      }));
  c.def(
      "__eq__",
      [](const py::object& self, const py::object& other) {
        if (!py::isinstance<Slam2DConfig>(other)) return false;
        for (const std::string& name : configFields())
          if (!self.attr(name.c_str()).equal(other.attr(name.c_str()))) return false;
        return true;
      },
      py::is_operator());
  c.def("__repr__", [](const py::object& self) {
    // The attributes that differ from the defaults, as a call that makes this configuration.
    py::object defaults = py::cast(Slam2DConfig{});
    std::string out = "Slam2DConfig(";
    bool first = true;
    for (const std::string& name : configFields()) {
      py::object v = self.attr(name.c_str());
      if (v.equal(defaults.attr(name.c_str()))) continue;
      out += (first ? "" : ", ") + name + "=" + py::repr(v).cast<std::string>();
      first = false;
    }
    return out + ")";
  });

  py::class_<PySlam>(m, "Slam2D", R"doc(
2D laser SLAM with submaps and loop closure (Hess et al. 2016, Cartographer's method):
``add_scan`` each scan with its raw odometry, ``finish()``, then read ``trajectory``,
``loops``, ``graph`` and the map. Poses are the robot's (base) in a world that starts at the
first odometry pose (x, y in m, theta in rad).
)doc")
      .def(py::init([](std::optional<Slam2DConfig> config, ArrayLike sensor_to_base) {
             return makeSlam(config, boundedPose(sensor_to_base, "sensor_to_base"));
           }),
           py::arg("config") = py::none(),
           py::arg("sensor_to_base") = py::make_tuple(0.0, 0.0, 0.0), R"doc(
Parameters
----------
config : Slam2DConfig, optional
    Default: ``Slam2DConfig()``.
sensor_to_base : array_like
    The laser on the robot: (x, y, theta) in m and rad, or a (4, 4) transform.

Raises
------
ValueError
    a configuration value out of its range.
)doc")
      .def(
          "add_scan",
          [](PySlam& p, ArrayLike angles, ArrayLike ranges, std::optional<ArrayLike> odometry,
             std::optional<double> stamp) {
            ObjectGuard guard(p.mutex, "Slam2D");
            if (p.finished()) throw py::value_error("add_scan after finish()");
            LaserScan scan;
            scan.angles = beamVector(angles, "angles");
            scan.ranges = beamVector(ranges, "ranges");
            std::optional<Pose2D> odo;
            if (odometry) odo = boundedPose(*odometry, "odometry");
            if (stamp && !std::isfinite(*stamp))
              throw py::value_error("stamp must be finite (None: no stamp), got " +
                                    py::repr(py::float_(*stamp)).cast<std::string>());
            const double t = stamp ? *stamp : std::numeric_limits<double>::quiet_NaN();
            {
              py::gil_scoped_release release;
              p.slam->addScan(scan, odo, t);
            }
            p.stamps.push_back(t);
          },
          py::arg("angles"), py::arg("ranges"), py::kw_only(), py::arg("odometry") = py::none(),
          py::arg("stamp") = py::none(), R"doc(
Add the next scan: ``add_scan(*scan.laser, odometry=scan.odometry, stamp=scan.stamp)``.

Parameters
----------
angles : array_like, shape (B,)
    Radians, counter-clockwise, x forward, within [-2 pi, 2 pi]: the order ``Scan.laser`` and
    :func:`read_scan_log` give, (angles, ranges).
ranges : array_like, shape (B,)
    Metres; NaN: no return (the beam is skipped).
odometry : array_like, optional, keyword-only
    The robot's raw odometry (base -> odometry world): (x, y, theta) or (4, 4); coordinates
    beyond 1e9 m are refused.
stamp : float, optional, keyword-only
    Seconds, finite (the motion filter's time limit applies only with stamps).

Raises
------
ValueError
    no beams, lengths differ, an angle not finite or beyond 2 pi (ranges given first?),
    non-finite odometry or stamp, or after finish().
CapacityError
    the maps outgrow the memory budget.
)doc")
      .def(
          "finish",
          [](PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            if (p.finished()) return;
            {
              py::gil_scoped_release release;
              p.slam->finish();
              p.keepResult();
            }
          },
          "Optimise the graph once more and build the map; further add_scan calls are refused.")
      .def_property_readonly(
          "trajectory",
          [](const PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            return poses2dArray(p.result ? p.result->trajectory : p.slam->trajectory());
          },
          "(N, 3) float64: x (m), y (m), theta (rad) of the robot at every scan added "
          "(after finish: optimised).")
      .def_property_readonly(
          "stamps",
          [](const PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            return doublesArray(p.stamps);
          },
          "(N,) float64: the stamps given to add_scan (NaN where none), in the order added.")
      .def_property_readonly(
          "node_scans",
          [](const PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            const auto& n = p.result ? p.result->node_scans : p.slam->nodeScans();
            std::vector<long long> v(n.begin(), n.end());
            return arrayFrom(v, {py::ssize_t(v.size())});
          },
          "(K,) int64: the scan index of every node (graph vertex).")
      .def_property_readonly(
          "loops",
          [](const PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            py::list out;
            for (const LoopClosure2D& l : p.result ? p.result->loops : p.slam->loops()) {
              py::dict d;
              d["node"] = l.node;
              d["submap"] = l.submap;
              d["anchor"] = l.anchor;
              d["score"] = l.score;
              d["edge"] = l.edge;
              out.append(d);
            }
            return out;
          },
          "list of dict: the loop closures kept (node, submap, anchor node, score, edge).")
      .def_property_readonly(
          "graph",
          [](const PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            PyPoseGraph g;
            g.dimension = 2;
            g.graph2d = p.result ? p.result->graph : p.slam->graph();
            return g;
          },
          "PoseGraph: a copy of the pose graph (one vertex per node).")
      .def_property_readonly(
          "stats",
          [](const PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            const Slam2DStats& s = p.result ? p.result->stats : p.slam->stats();
            py::dict d;
            d["scans"] = s.scans;
            d["nodes"] = s.nodes;
            d["submaps"] = s.submaps;
            d["finished_submaps"] = s.finished_submaps;
            d["loop_searches"] = s.loop_searches;
            d["loop_candidates"] = s.loop_candidates;
            d["loops_found"] = s.loops_found;
            d["loops_rejected"] = s.loops_rejected;
            d["optimizations"] = s.optimizations;
            d["local_seconds"] = s.local_seconds;
            d["insert_seconds"] = s.insert_seconds;
            d["loop_seconds"] = s.loop_seconds;
            d["optimize_seconds"] = s.optimize_seconds;
            d["map_seconds"] = s.map_seconds;
            d["final_chi2_initial"] = s.final_chi2_initial;
            d["final_chi2"] = s.final_chi2;
            d["final_iterations"] = s.final_iterations;
            return d;
          },
          "dict: counts and seconds per phase (Slam2DStats).")
      .def_property_readonly(
          "config",
          [](const PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            return p.result ? p.result->config : p.slam->config();
          },
          "Slam2DConfig: a copy of the configuration in use.")
      .def(
          "map",
          [](const PySlam& p) {
            ObjectGuard guard(p.mutex, "Slam2D");
            return withMap(p, [](const LogOddsGrid2D& g) { return mapDict(g); });
          },
          R"doc(
The map: after finish the final one; before, the map so far, built now as finish() builds
it from every node at its current estimate (without the final optimisation). A dict with log_odds (H, W) float32 (row r, column c is the cell
(min_i + c, min_j + r) of `resolution` m, spanning [i r, (i+1) r) x [j r, (j+1) r); NaN
unknown), min_i, min_j, resolution, occupied_cells, known_cells.
)doc")
      .def(
          "map_image",
          [](const PySlam& p, const std::string& kind) {
            ObjectGuard guard(p.mutex, "Slam2D");
            if (kind != "trinary" && kind != "probability")
              throw py::value_error("kind must be 'trinary' or 'probability', got '" + kind + "'");
            return withMap(p, [&kind](const LogOddsGrid2D& g) {
              return mapServerDict(kind == "trinary" ? g.trinaryImage() : g.probabilityImage());
            });
          },
          py::arg("kind") = "trinary", R"doc(
The map as map_server sees it: dict with image (H, W) uint8 (row 0 at the top; trinary:
occupied 0, free 254, unknown 205; probability: 255 (1 - p)), resolution, origin (x, y of the
lower-left corner, m), mode. Before finish: of the map so far (see :meth:`map`).
)doc")
      .def(
          "write_map",
          [](const PySlam& p, const std::filesystem::path& path, const std::string& kind) {
            ObjectGuard guard(p.mutex, "Slam2D");
            if (kind != "trinary" && kind != "probability")
              throw py::value_error("kind must be 'trinary' or 'probability', got '" + kind + "'");
            withMap(p, [&](const LogOddsGrid2D& g) {
              writeMapImage(path.string(),
                            kind == "trinary" ? g.trinaryImage() : g.probabilityImage());
              return 0;
            });
          },
          py::arg("path"), py::arg("kind") = "trinary",
          "Write the map as map_server files: `path` (.pgm) and the .yaml beside it (what "
          "`metricmap slam2d --out-map` writes for 'trinary').")
      .def(py::pickle(&slamState, &slamFromState))
      .def("__repr__", [](const PySlam& p) {
        ObjectGuard guard(p.mutex, "Slam2D");
        const std::size_t scans = p.stamps.size();
        return "<metricmap.Slam2D " + std::to_string(scans) + " scans, " +
               (p.result ? std::to_string(p.result->node_scans.size()) + " nodes, " +
                               std::to_string(p.result->loops.size()) + " loops, finished>"
                         : std::string("running>"));
      });

  m.def(
      "run_slam2d",
      [](py::object source, py::object frames, std::optional<Slam2DConfig> config,
         bool loop_closure, py::object progress) {
        ProgressWatch watch(progress);
        py::object holder;
        PySource& s = sourceFrom(source, holder);
        const SourceInfo& info = s.source->info();
        if (!info.planar)
          throw InputError(info.path + ": slam2d needs 2D laser scans (a CARMEN log); this is a " +
                           info.kind + " source of 3D scans");
        const std::vector<std::size_t> f = selectedFrames(frames, s.source->size());
        Slam2DConfig c = config ? *config : Slam2DConfig{};
        if (!loop_closure) {
          // As --no-loop-closure with --set: a loop parameter given has no effect.
          const Slam2DConfig defaults;
          for (const ParameterSpec& spec : slam2DParameterSchema())
            if (isLoopClosureParameter(spec.name) &&
                slam2DParameterValue(c, spec.name) != slam2DParameterValue(defaults, spec.name))
              throw py::value_error("config." + spec.name +
                                    " has no effect with loop_closure=False");
          c.loop_every_n_nodes = c.wide_every_n_nodes = static_cast<std::size_t>(-1);
        }
        auto p = std::make_unique<PySlam>();
        {
          ObjectGuard guard(s.mutex, "ScanSource");
          py::gil_scoped_release release;
          Slam2DRun run = runSlam2D(
              *s.source, f, c, info.path,
              [&watch](std::size_t done, std::size_t total, const Slam2D&) { watch(done, total); });
          p->slam = std::move(run.slam);
          p->stamps = std::move(run.scan_stamps);
          p->keepResult();
        }
        return p;
      },
      py::arg("source"), py::arg("frames") = py::none(), py::arg("config") = py::none(),
      py::arg("loop_closure") = true, py::kw_only(), py::arg("progress") = py::none(), R"doc(
Run :class:`Slam2D` over a planar source (a CARMEN log), as `metricmap slam2d` does: the
source's laser offset as sensor_to_base, each scan's beams, raw odometry and stamp.

Parameters
----------
source : ScanSource or str or os.PathLike
frames : sequence of int, optional
    Strictly increasing scan indices (default: all).
config : Slam2DConfig, optional
loop_closure : bool
    False: local SLAM only (`--no-loop-closure`).
progress : callable(done, total), optional, keyword-only
    Called with the scans done and the scans selected, at most every 20 ms and after the last
    scan (before the final optimisation).

Returns
-------
Slam2D
    finished.

Raises
------
InputError
    not a planar source, a scan that cannot be read or is not a 2D laser scan, or odometry
    the SLAM refuses (not finite, or beyond +-1e6 m); the message names the scan.
CapacityError
    the maps outgrow the memory budget.
ValueError
    a frame out of range, frames empty or not strictly increasing.
KeyboardInterrupt
    Ctrl-C (checked between scans); nothing is returned. Any exception `progress` raises
    likewise stops the run and reaches the caller.
)doc");
}

}  // namespace metricmap::python
