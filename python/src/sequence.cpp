// metricmap.ScanSource / Scan / run_odometry / SequenceMapper: the sequence layer
// (datasets/scan_source.h, sequence/odometry_run.h, sequence/sequence_mapper.h).
#include <algorithm>
#include <cmath>
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
#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/sequence/odometry_run.h"
#include "metricmap/sequence/sensor_profile.h"
#include "metricmap/sequence/sequence_mapper.h"
#include "object_lock.h"
#include "poses.h"
#include "progress.h"
#include "sequence.h"

namespace metricmap::python {

namespace {

/// The figures of no error at all are NaN (numpy's mean of nothing), not 0.
py::dict statsDict(const ErrorStatistics& s) {
  const auto figure = [&s](double v) {
    return s.count > 0 ? v : std::numeric_limits<double>::quiet_NaN();
  };
  py::dict d;
  d["count"] = s.count;
  d["rmse"] = figure(s.rmse);
  d["mean"] = figure(s.mean);
  d["median"] = figure(s.median);
  d["std"] = figure(s.stddev);
  d["min"] = figure(s.min);
  d["max"] = figure(s.max);
  return d;
}

py::object scanLaser(const Scan& s) {
  if (!s.laser) return py::none();
  return py::make_tuple(doublesArray(s.laser->angles), doublesArray(s.laser->ranges));
}

py::dict infoDict(const SourceInfo& info) {
  py::dict d;
  d["kind"] = info.kind;
  d["path"] = info.path;
  d["sensor_to_base"] = matrix4(info.sensor_to_base.matrix());
  d["reference_poses"] = posesArray(info.reference.poses);
  d["reference_stamps"] = doublesArray(info.reference.stamps);
  d["reference_path"] = info.reference_path;
  d["stamps"] = doublesArray(info.stamps);
  d["point_times"] = info.point_times;
  d["planar"] = info.planar;
  return d;
}

std::size_t checkedIndex(const PySource& s, py::ssize_t i) {
  const py::ssize_t n = static_cast<py::ssize_t>(s.source->size());
  if (i < 0) i += n;
  if (i < 0 || i >= n)
    throw py::index_error("scan index out of range (the source has " + std::to_string(n) +
                          " scans)");
  return static_cast<std::size_t>(i);
}

struct PyMapper {
  py::object source_object;  // keeps the source alive
  PySource* source = nullptr;
  ScanMapperConfig config;
  std::unique_ptr<SequenceMapper> mapper;
  bool built = false;
  mutable ObjectMutex mutex;  ///< serialises the object's calls
  const ScanMapper& maps() const {
    if (!built) throw py::value_error("no map yet: call build(poses) first");
    return mapper->maps();
  }
};

py::dict odometryRunDict(const OdometryRun& r, const SourceInfo& info) {
  py::dict d;
  std::vector<double> stamps, ms;
  py::list names;
  std::vector<long long> frames;
  for (const OdometryFrame& f : r.frames) {
    stamps.push_back(f.stamp);
    ms.push_back(f.ms);
    names.append(f.name);
    frames.push_back(static_cast<long long>(f.index));
  }
  d["poses"] = posesArray(r.trajectory.poses);
  d["stamps"] = doublesArray(stamps);
  d["frames"] = arrayFrom(frames, {py::ssize_t(frames.size())});
  d["names"] = names;
  d["sensor_poses"] = posesArray(odometrySensorPoses(r, info));
  d["convention"] = r.convention;
  d["deskewed"] = r.deskewed;
  d["milliseconds"] = doublesArray(ms);
  d["read_seconds"] = r.read_seconds;
  py::dict c;
  c["max_range"] = r.config.max_range;
  c["min_range"] = r.config.min_range;
  c["voxel_size"] = r.config.voxel_size;
  c["coarse_voxel_size"] = r.config.coarse_voxel_size;
  c["max_threshold"] = r.config.max_threshold;
  c["fine_threshold"] = r.config.fine_threshold;
  c["convergence"] = r.config.convergence;
  d["config"] = c;
  d["profile_used"] = r.profile.used;
  if (r.reference.empty()) {
    d["reference_poses"] = py::none();
  } else {
    d["reference_poses"] = posesArray(r.reference.poses);
  }
  if (!r.rpe) {
    d["rpe"] = py::none();
  } else {
    py::dict e;
    e["translation"] = doublesArray(r.rpe->translation);
    e["rotation_deg"] = doublesArray(r.rpe->rotation_deg);
    e["translation_stats"] = statsDict(r.rpe->translation_stats);
    e["rotation_stats"] = statsDict(r.rpe->rotation_stats);
    d["rpe"] = e;
  }
  return d;
}

}  // namespace

py::dict errorStatsDict(const ErrorStatistics& s) { return statsDict(s); }

PySource& sourceFrom(const py::handle& obj, py::object& holder) {
  if (py::isinstance<PySource>(obj)) {
    holder = py::reinterpret_borrow<py::object>(obj);
  } else {
    holder = py::module_::import("metricmap._metricmap").attr("open_scan_source")(obj);
  }
  return holder.cast<PySource&>();
}

void initSequence(py::module_& m) {
  py::class_<Scan>(m, "Scan", R"doc(
One scan of a :class:`ScanSource`, in its sensor frame. The arrays are read-only views of the
scan, which they keep alive.
)doc")
      .def_property_readonly(
          "points",
          [](py::object self) {
            const Scan& s = self.cast<const Scan&>();
            const float* p = s.points.empty() ? nullptr : s.points.points.front().data;
            return viewOf(p, {py::ssize_t(s.points.size()), 3},
                          {py::ssize_t(sizeof(pcl::PointXYZ)), py::ssize_t(sizeof(float))}, self);
          },
          "(N, 3) float32 view, metres, sensor frame; NaN rows where a beam gave no return.")
      .def_property_readonly(
          "intensity",
          [](py::object self) {
            const Scan& s = self.cast<const Scan&>();
            return viewOf(s.intensity.empty() ? nullptr : s.intensity.data(),
                          {py::ssize_t(s.intensity.size())}, {py::ssize_t(sizeof(float))}, self);
          },
          "(N,) float32 per-point intensity, or (0,) when the data has none.")
      .def_property_readonly(
          "point_times",
          [](py::object self) {
            const Scan& s = self.cast<const Scan&>();
            return viewOf(s.point_times.empty() ? nullptr : s.point_times.data(),
                          {py::ssize_t(s.point_times.size())}, {py::ssize_t(sizeof(double))}, self);
          },
          "(N,) float64 per-point time in seconds relative to `stamp`, or (0,).")
      .def_readonly("stamp", &Scan::stamp, "float: time stamp (s), NaN when unknown.")
      .def_readonly("index", &Scan::index, "int: position in the source (0-based).")
      .def_readonly("name", &Scan::name, "str: the file path, or 'LOG: line N'.")
      .def_property_readonly("laser", &scanLaser,
                             "(angles, ranges): two (B,) float64 arrays (rad, m; NaN: invalid "
                             "beam) for planar laser sources, else None.")
      .def_property_readonly(
          "odometry",
          [](const Scan& s) -> py::object {
            if (!s.odometry) return py::none();
            return matrix4(s.odometry->matrix());
          },
          "(4, 4) float64 raw odometry pose (base -> odometry world) the log gives, else None.")
      .def("__repr__", [](const Scan& s) {
        return "<metricmap.Scan " + std::to_string(s.index) + " '" + s.name +
               "': " + std::to_string(s.points.size()) + " points>";
      });

  py::class_<PySource>(m, "ScanSource", R"doc(
Scans from one place in acquisition order (a KITTI odometry root, a folder or .txt list of
.pcd/.ply/.bin/.npy scans, a CARMEN log): ``len(source)``, ``source[i]`` (negative indices
count from the end) and iteration give :class:`Scan` objects, read one at a time. Open with
:func:`open_scan_source`. Not for concurrent use from several threads (calls are serialised).
)doc")
      .def("__len__", [](const PySource& s) { return s.source->size(); })
      .def(
          "__getitem__",
          [](PySource& s, const py::object& index) -> py::object {
            if (py::isinstance<py::slice>(index)) {
              // A slice reads its scans now, as a list (frames= selects lazily in run functions)
              py::ssize_t start = 0, stop = 0, step = 0, length = 0;
              if (!index.cast<py::slice>().compute(static_cast<py::ssize_t>(s.source->size()),
                                                   &start, &stop, &step, &length))
                throw py::error_already_set();
              py::list out;
              for (py::ssize_t n = 0; n < length; ++n) {
                const auto k = static_cast<std::size_t>(start + n * step);
                ObjectGuard guard(s.mutex, "ScanSource");
                std::unique_ptr<Scan> scan;
                {
                  py::gil_scoped_release release;
                  scan = std::make_unique<Scan>(s.source->scan(k));
                }
                out.append(py::cast(std::move(scan)));
              }
              return std::move(out);
            }
            if (!py::isinstance<py::int_>(index) || py::isinstance<py::bool_>(index))
              throw py::type_error("ScanSource indices must be integers or slices, got " +
                                   std::string(py::str(py::type::of(index).attr("__name__"))));
            const std::size_t k = checkedIndex(s, index.cast<py::ssize_t>());
            ObjectGuard guard(s.mutex, "ScanSource");
            std::unique_ptr<Scan> scan;
            {
              py::gil_scoped_release release;
              scan = std::make_unique<Scan>(s.source->scan(k));
            }
            return py::cast(std::move(scan));
          },
          py::arg("index"),
          "source[i] -> Scan (negative i counts from the end); source[a:b:c] -> list of Scan, "
          "read now.")
      .def_property_readonly(
          "info", [](const PySource& s) { return infoDict(s.source->info()); },
          "dict: kind ('kitti', 'folder', 'carmen', 'bag'), path, sensor_to_base (4, 4) float64, "
          "reference_poses (R, 4, 4) float64 (sensor -> reference world; (0, 4, 4) when none), "
          "reference_stamps (R,) or (0,), reference_path, stamps (N,) float64 seconds or (0,), "
          "point_times (bool), planar (bool).")
      .def_property_readonly(
          "path", [](const PySource& s) { return s.source->info().path; }, "str: as opened.")
      .def("__repr__", [](const PySource& s) {
        return "<metricmap.ScanSource " + s.source->info().kind + " '" + s.source->info().path +
               "': " + std::to_string(s.source->size()) + " scans>";
      });

  m.def(
      "open_scan_source",
      [](const std::filesystem::path& path, const std::string& format,
         std::optional<std::string> sequence, std::optional<std::filesystem::path> reference_poses,
         std::optional<std::filesystem::path> times, std::optional<std::string> topic) {
        // An option the source would ignore is refused, never dropped.
        const std::string kind = scanSourceKind(path.string(), format);
        for (auto [given, name] :
             {std::pair{sequence.has_value(), "sequence"},
              std::pair{reference_poses.has_value(), "reference_poses"},
              std::pair{times.has_value(), "times"}, std::pair{topic.has_value(), "topic"}}) {
          const std::string why = given ? ignoredSourceOption(kind, name) : std::string();
          if (!why.empty()) throw py::value_error(std::string(name) + " is ignored " + why);
        }
        ScanSourceOptions o;
        if (topic) o.topic = *topic;
        o.format = format;
        if (sequence) o.sequence = *sequence;
        if (reference_poses) o.reference_poses = reference_poses->string();
        if (times) o.times = times->string();
        auto s = std::make_unique<PySource>();
        {
          py::gil_scoped_release release;
          s->source = openScanSource(path.string(), o);
        }
        return s;
      },
      py::arg("path"), py::arg("format") = "auto", py::arg("sequence") = py::none(),
      py::arg("reference_poses") = py::none(), py::arg("times") = py::none(),
      py::arg("topic") = py::none(), R"doc(
Open a scan source (what `metricmap odometry SOURCE` reads).

Parameters
----------
path : str or os.PathLike
    A KITTI odometry root (has ``sequences/``), a folder of scans (.pcd .ply .bin .npy, one
    format, natural order), a .txt list of scan paths, a CARMEN log (.clf/.log, .gz/.bz2), or
    a ROS bag where the library reads them.
format : {'auto', 'kitti', 'folder', 'carmen', 'bag'}
    How to read `path` ('auto': from the path).
sequence : str, optional
    KITTI sequence under the root (default '00'). Options the source would ignore
    (`sequence` off KITTI, `topic` off a bag, `times` or `reference_poses` on a CARMEN log,
    `times` on a bag) are refused with ValueError.
reference_poses : str or os.PathLike, optional
    Reference poses (KITTI 12-number or TUM 8-number rows, one per scan) replacing the
    source's own (``poses/NN.txt``, a folder's ``poses.txt``).
times : str or os.PathLike, optional
    Stamps file (one number per line, seconds) replacing ``times.txt``.
topic : str, optional
    Bag topic to read (default: the bag's only PointCloud2 / LaserScan topic).

Returns
-------
ScanSource

Raises
------
InputError (an OSError and ValueError)
    the path is none of these, or its files are inconsistent.
ValueError
    a bad option value.
)doc");

  m.def(
      "run_odometry",
      [](py::object source, py::object frames, std::optional<std::string> profile,
         std::optional<double> max_range, std::optional<double> min_range,
         std::optional<double> voxel_size, const std::string& deskew, unsigned threads,
         py::object progress) {
        ProgressWatch watch(progress);
        py::object holder;
        PySource& s = sourceFrom(source, holder);
        OdometryRunOptions o;
        o.frames = framesFrom(frames, "frames");
        const SourceInfo& info = s.source->info();
        const std::vector<std::string>& names = sensorProfileNames();
        if (profile && std::find(names.begin(), names.end(), *profile) == names.end())
          throw py::value_error("profile must be 'auto', 'kitti' or None, got '" + *profile + "'");
        if (profile && max_range && min_range && voxel_size)
          throw py::value_error(
              "profile has no effect with max_range, min_range and voxel_size all given: it sets "
              "only the values not given");
        const bool automatic =
            profile ? *profile == "auto" : info.conventions.default_profile == "auto";
        o.profile.max_range = automatic && !max_range;
        o.profile.min_range = automatic && !min_range;
        o.profile.voxel_size = automatic && !voxel_size;
        for (auto [v, name] : {std::pair{max_range, "max_range"}, std::pair{min_range, "min_range"},
                               std::pair{voxel_size, "voxel_size"}})
          if (v && !(std::isfinite(*v) && *v >= 0.0))
            throw py::value_error(std::string(name) + " must be finite and >= 0");
        if (max_range) o.config.max_range = *max_range;
        if (min_range) o.config.min_range = *min_range;
        if (voxel_size) o.config.voxel_size = *voxel_size;
        o.config.threads = threads;
        if (deskew == "auto") {
          o.deskew = DeskewMode::Auto;
        } else if (deskew == "off") {
          o.deskew = DeskewMode::Off;
        } else if (deskew == "azimuth") {
          o.deskew = DeskewMode::Azimuth;
        } else {
          throw py::value_error("deskew must be 'auto', 'off' or 'azimuth', got '" + deskew + "'");
        }
        OdometryRun run;
        {
          ObjectGuard guard(s.mutex, "ScanSource");
          py::gil_scoped_release release;
          run = runOdometry(*s.source, o,
                            [&watch](const OdometryFrame&, std::size_t done, std::size_t total) {
                              watch(done, total);
                            });
        }
        return odometryRunDict(run, info);
      },
      py::arg("source"), py::arg("frames") = py::none(), py::arg("profile") = py::none(),
      py::arg("max_range") = py::none(), py::arg("min_range") = py::none(),
      py::arg("voxel_size") = py::none(), py::arg("deskew") = "auto", py::arg("threads") = 0u,
      py::kw_only(), py::arg("progress") = py::none(), R"doc(
LiDAR odometry over a scan source: what `metricmap odometry` computes (sequence/odometry_run).

Parameters
----------
source : ScanSource or str or os.PathLike
    The scans (a path is opened with :func:`open_scan_source`'s defaults).
frames : sequence of int, optional
    Scan indices, strictly increasing (default: every scan).
profile : {'auto', 'kitti'}, optional
    Range window and voxel: 'kitti' (100 m, 3 m, 1 m voxel) or 'auto' (from the first scan's
    ranges). Default: 'kitti' for a KITTI source, 'auto' otherwise. Giving it with all three
    of max_range, min_range and voxel_size is a ValueError (it would set nothing).
max_range, min_range, voxel_size : float, optional
    Metres; given values replace the profile's.
deskew : {'auto', 'off', 'azimuth'}
    'auto': with the scans' per-point times when they have them; 'azimuth': times from the
    azimuth of a spinning sensor.
threads : int
    Threads for the scan-to-map pairing (0: all); the poses do not depend on it.
progress : callable(done, total), optional, keyword-only
    Called with the frames done and selected, at most every 20 ms and after the last.

Returns
-------
dict
    poses (N, 4, 4) float64 in the source's pose-file convention (KITTI: camera 0 in the frame
    of camera 0 of the first frame, as poses/NN.txt; otherwise the sensor in the frame of the
    first scan), stamps (N,) float64 s (NaN when unknown), frames (N,) int64, names,
    sensor_poses (N, 4, 4) sensor -> map world (for :class:`SequenceMapper`), convention,
    deskewed, milliseconds (N,), read_seconds, config (the range window and voxel used),
    profile_used, reference_poses (N, 4, 4) or None, rpe (per-frame relative error against
    the reference: translation (N-1,) m, rotation_deg (N-1,), *_stats) or None.

Raises
------
InputError
    a scan that cannot be read or registered.
ValueError
    frames empty, not strictly increasing or out of range, a bad option.
KeyboardInterrupt
    Ctrl-C (checked between frames); nothing is returned. Any exception `progress` raises
    likewise stops the run and reaches the caller.
)doc");

  py::class_<PyMapper>(m, "SequenceMapper", R"doc(
Maps of a sequence built from a trajectory (sequence/sequence_mapper): the scans are read
again from the source, one at a time, and fused at the given sensor -> map world poses into a
2D hit map, optionally the global cloud and a 2D log-odds grid. ``build`` again with a
corrected trajectory rebuilds them. The map's plane and up axis follow the source (KITTI: the
XZ plane of camera 0, up -y; otherwise XY, up +z).
)doc")
      .def(py::init([](py::object source, double map_resolution, unsigned min_hits,
                       double min_range, std::optional<double> max_range, double voxel,
                       std::optional<double> min_height, std::optional<double> max_height,
                       bool keep_global_cloud, double occupancy_2d_resolution,
                       std::optional<std::pair<double, double>> band_2d,
                       std::optional<double> occupancy_2d_max_range) {
             auto p = std::make_unique<PyMapper>();
             PySource& s = sourceFrom(source, p->source_object);
             p->source = &s;
             ScanMapperConfig& c = p->config;
             const MapConvention convention = mapConvention(s.source->info());
             c.up = convention.up;
             c.plane = convention.plane;
             c.map_resolution = map_resolution;
             c.min_hits = min_hits;
             c.min_range = min_range;
             if (max_range) c.max_range = *max_range;
             c.voxel = voxel;
             if (min_height) c.min_height = *min_height;
             if (max_height) c.max_height = *max_height;
             c.keep_global_cloud = keep_global_cloud;
             if (occupancy_2d_resolution > 0.0 || std::isnan(occupancy_2d_resolution)) {
               Occupancy2DConfig g;
               g.params.resolution = occupancy_2d_resolution;
               if (occupancy_2d_max_range) g.params.max_range = *occupancy_2d_max_range;
               if (band_2d) {
                 g.band_min = band_2d->first;
                 g.band_max = band_2d->second;
               }
               c.occupancy_2d = g;
             } else {  // no 2D grid: its options would change nothing
               for (auto [given, name] :
                    {std::pair{band_2d.has_value(), "band_2d"},
                     std::pair{occupancy_2d_max_range.has_value(), "occupancy_2d_max_range"}})
                 if (given)
                   throw py::value_error(std::string(name) +
                                         " has no effect without occupancy_2d_resolution > 0: "
                                         "there is no 2D log-odds grid");
             }
             p->mapper = std::make_unique<SequenceMapper>(*s.source, c);
             return p;
           }),
           py::arg("source"), py::arg("map_resolution") = 0.1, py::arg("min_hits") = 1u,
           py::arg("min_range") = 0.0, py::arg("max_range") = py::none(), py::arg("voxel") = 0.0,
           py::arg("min_height") = py::none(), py::arg("max_height") = py::none(),
           py::arg("keep_global_cloud") = false, py::arg("occupancy_2d_resolution") = 0.0,
           py::arg("band_2d") = py::none(), py::arg("occupancy_2d_max_range") = py::none(),
           R"doc(
Parameters
----------
source : ScanSource or str or os.PathLike
map_resolution : float
    Cell of the 2D hit map (m).
min_hits : int
    Hits that make a hit-map cell occupied.
min_range, max_range : float
    Range band of each scan in its sensor frame (m; max_range None: no limit).
voxel : float
    Average each scan and the global cloud in cells of this size (m; 0: off).
min_height, max_height : float, optional
    Height band of the hit map along the map's up axis (m; None: unbounded).
keep_global_cloud : bool
    Accumulate the scans in the world (:meth:`global_cloud`).
occupancy_2d_resolution : float
    Cell of a 2D log-odds grid (m; 0: no grid).
band_2d : (float, float), optional
    Heights about the sensor (m) whose points the 2D grid casts (None: (-0.5, 0.5); 2D laser
    scans: all).
occupancy_2d_max_range : float, optional
    Beams longer are cut and mark free space only (m; None: no cut). It and band_2d need
    occupancy_2d_resolution > 0 (a ValueError otherwise: they would change nothing).

Raises
------
ValueError
    a bad parameter.
)doc")
      .def(
          "build",
          [](py::object self, ArrayLike poses, py::object frames, py::object progress) {
            PyMapper& p = self.cast<PyMapper&>();
            ObjectGuard guard(p.mutex, "SequenceMapper");
            ProgressWatch watch(progress);
            const std::vector<Eigen::Isometry3d> t = posesFrom(poses, "poses");
            const std::vector<std::size_t> f = framesFrom(frames, "frames");
            {
              ObjectGuard source_guard(p.source->mutex, "ScanSource");
              py::gil_scoped_release release;
              p.built = false;
              p.mapper->build(t, f,
                              [&watch](const FrameReport&, std::size_t done, std::size_t total) {
                                watch(done, total);
                              });
              p.built = true;
            }
            return self;
          },
          py::arg("poses"), py::arg("frames") = py::none(), py::kw_only(),
          py::arg("progress") = py::none(), R"doc(
Forget the maps and fuse the scans `frames` (default: every scan) at `poses`. While it runs and
after it is stopped (Ctrl-C, an error) the mapper has no maps: build again.

Parameters
----------
poses : array_like, shape (N, 4, 4)
    Sensor -> map world, one per frame (e.g. ``run_odometry(...)['sensor_poses']`` or
    :func:`reference_sensor_poses`).
frames : sequence of int, optional
    Increasing scan indices, as many as poses (not empty).
progress : callable(done, total), optional, keyword-only
    Called with the scans fused and selected, at most every 20 ms and after the last.

Returns
-------
SequenceMapper
    self.
)doc")
      .def(
          "hit_map",
          [](const PyMapper& p) {
            ObjectGuard guard(p.mutex, "SequenceMapper");
            const MapImage image = p.maps().map().image();
            py::dict d;
            py::array_t<std::uint32_t> a({py::ssize_t(image.height), py::ssize_t(image.width)});
            if (!image.hits.empty())
              std::copy(image.hits.begin(), image.hits.end(), a.mutable_data());
            d["hits"] = a;
            d["resolution"] = image.resolution;
            d["origin"] = py::make_tuple(image.origin_x, image.origin_y);
            return d;
          },
          R"doc(
The 2D hit map: dict with hits (H, W) uint32 (points per cell, row 0 at the top), resolution
(m) and origin (world position of the lower-left corner along the plane's two axes).
)doc")
      .def(
          "occupied_cells",
          [](const PyMapper& p) {
            ObjectGuard guard(p.mutex, "SequenceMapper");
            return p.maps().occupiedCells();
          },
          "int: hit-map cells with at least `min_hits` hits.")
      .def(
          "write_map",
          [](const PyMapper& p, const std::filesystem::path& path, const std::string& kind) {
            ObjectGuard guard(p.mutex, "SequenceMapper");
            if (kind == "hits") {
              const MapImage image = p.maps().map().image();
              if (image.width == 0) throw InputError("the map is empty: nothing to write");
              writeMapImage(path.string(), mapServerImage(image, p.config.min_hits));
            } else if (kind == "occupancy_2d") {
              const LogOddsGrid2D* g = p.maps().occupancy2D();
              if (g == nullptr)
                throw py::value_error("no 2D log-odds grid: give occupancy_2d_resolution > 0");
              writeMapImage(path.string(), g->trinaryImage());
            } else {
              throw py::value_error("kind must be 'hits' or 'occupancy_2d', got '" + kind + "'");
            }
          },
          py::arg("path"), py::arg("kind") = "hits", R"doc(
Write a map_server map: `path` (.pgm) and the .yaml beside it; kind 'hits' (occupied where
>= min_hits) or 'occupancy_2d' (trinary log-odds grid).
)doc")
      .def(
          "global_cloud",
          [](const PyMapper& p) {
            ObjectGuard guard(p.mutex, "SequenceMapper");
            ScanMapper::Cloud c;
            if (!p.config.keep_global_cloud)
              throw py::value_error(
                  "no global cloud is kept: make the mapper with "
                  "keep_global_cloud=True");
            {
              const ScanMapper& maps = p.maps();
              py::gil_scoped_release release;
              c = maps.globalCloud();
            }
            py::array_t<float> a({py::ssize_t(c.size()), py::ssize_t(3)});
            float* d = a.mutable_data();
            for (std::size_t i = 0; i < c.size(); ++i)
              for (int k = 0; k < 3; ++k) d[3 * i + k] = c.points[i].data[k];
            return a;
          },
          "(M, 3) float32 copy of the fused scans in the world. ValueError without "
          "keep_global_cloud.")
      .def(
          "occupancy_2d",
          [](const PyMapper& p) -> py::object {
            ObjectGuard guard(p.mutex, "SequenceMapper");
            const LogOddsGrid2D* g = p.maps().occupancy2D();
            if (g == nullptr) return py::none();
            py::dict d;
            py::array_t<float> a({py::ssize_t(g->height()), py::ssize_t(g->width())});
            if (g->width() * g->height() > 0)
              std::copy(g->data(), g->data() + g->width() * g->height(), a.mutable_data());
            d["log_odds"] = a;
            d["min_i"] = g->minI();
            d["min_j"] = g->minJ();
            d["resolution"] = g->params().resolution;
            d["occupied_cells"] = g->occupiedCells();
            d["known_cells"] = g->knownCells();
            return d;
          },
          R"doc(
The 2D log-odds grid or None: dict with log_odds (H, W) float32 (row r, column c is cell
(min_i + c, min_j + r), NaN unknown), min_i, min_j, resolution (m), occupied_cells,
known_cells.
)doc")
      .def_property_readonly(
          "poses",
          [](const PyMapper& p) {
            ObjectGuard guard(p.mutex, "SequenceMapper");
            return posesArray(p.maps().poses());
          },
          "(N, 4, 4) float64: the poses used in the last build.");

  m.def(
      "reference_sensor_poses",
      [](py::object source, py::object frames) {
        py::object holder;
        PySource& s = sourceFrom(source, holder);
        std::vector<std::size_t> f = framesFrom(frames, "frames");
        if (f.empty())
          for (std::size_t k = 0; k < s.source->size(); ++k) f.push_back(k);
        return posesArray(referenceSensorPoses(*s.source, f));
      },
      py::arg("source"), py::arg("frames") = py::none(), R"doc(
Sensor -> map world poses of `frames` (default: all) from the source's reference poses
(KITTI: P Tr, camera 0 of the first frame as the world, as `metricmap kitti`).

Returns
-------
numpy.ndarray, shape (N, 4, 4), float64

Raises
------
InputError
    the source has no reference poses.
)doc");
}

}  // namespace metricmap::python
