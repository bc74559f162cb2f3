// metricmap.Slam3D / Slam3DConfig / run_slam3d: 3D LiDAR SLAM with loop closure
// (slam3d/slam3d.h).
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "declared_config.h"
#include "metricmap/slam3d/slam3d.h"
#include "metricmap/slam3d/slam3d_config.h"
#include "metricmap/slam3d/slam3d_run.h"
#include "object_lock.h"
#include "parameter_list.h"
#include "poses.h"
#include "progress.h"
#include "sequence.h"

namespace metricmap::python {
namespace {

pcl::PointCloud<pcl::PointXYZ> cloudFrom(const py::handle& obj) {
  const PointsArray a = pointsFromArray(pointsOf(obj), "points", true);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.resize(a.span.size);
  for (std::size_t i = 0; i < a.span.size; ++i) {
    const float* p = a.span.at(i);
    cloud[i] = pcl::PointXYZ(p[0], p[1], p[2]);
  }
  return cloud;
}

py::dict reportDict(const Slam3DFrameReport& r) {
  py::dict d;
  d["node"] = r.node;
  d["searched"] = r.searched;
  d["candidates"] = r.candidates;
  d["verified"] = r.verified;
  d["optimized"] = r.optimized;
  return d;
}

py::list loopsList(const Slam3D& s) {
  py::list out;
  for (const Slam3DLoop& l : s.loopChecks()) {
    py::dict d;
    d["from"] = l.from;
    d["to"] = l.to;
    d["method"] = l.method;
    d["descriptor_distance"] = l.descriptor_distance;
    d["accepted"] = l.check.accepted;
    d["relation"] = matrix4(l.check.relation.matrix());
    d["overlap"] = l.check.overlap;
    d["structure_overlap"] = l.check.structure_overlap;
    d["rmse"] = l.check.rmse;
    d["reason"] = l.check.reason;
    out.append(d);
  }
  return out;
}

py::dict timingDict(const Slam3DTiming& t) {
  py::dict d;
  d["descriptors"] = t.descriptors;
  d["search"] = t.search;
  d["verify"] = t.verify;
  d["optimize"] = t.optimize;
  d["optimizations"] = t.optimizations;
  return d;
}

}  // namespace

void initSlam3D(py::module_& m) {
  py::class_<Slam3DConfig> c(m, "Slam3DConfig", R"doc(
Parameters of :class:`Slam3D` (slam3d/slam3d_config.h), one attribute each;
``Slam3DConfig(loop_radius=5.0, ...)`` sets attributes by name. Each value is range-checked when
set (ValueError naming it).
)doc");
  bindKeywordConstructor(c, "Slam3DConfig");
  bindDeclaredFields(c, slam3DParameterSchema(), &slam3DParameterValue, &setSlam3DParameterValue);
  c.def(py::pickle(
      [](const Slam3DConfig& s) {
        py::dict d;
        for (const std::string& n : slam3DParameterNames())
          d[n.c_str()] = slam3DParameterValue(s, n);
        return d;
      },
      [](const py::dict& d) {
        Slam3DConfig config;
        for (auto item : d)
          setSlam3DParameterValue(config, item.first.cast<std::string>(),
                                  item.second.cast<double>());
        return config;
      }));
  c.def(
      "__eq__",
      [](const Slam3DConfig& a, const py::object& other) {
        if (!py::isinstance<Slam3DConfig>(other)) return false;
        const Slam3DConfig& b = other.cast<const Slam3DConfig&>();
        for (const std::string& n : slam3DParameterNames())
          if (slam3DParameterValue(a, n) != slam3DParameterValue(b, n)) return false;
        return true;
      },
      py::is_operator());
  c.def("__repr__", [](const Slam3DConfig& s) {
    std::string out = "Slam3DConfig(";
    bool first = true;
    for (const std::string& n : slam3DParameterNames()) {
      out += (first ? "" : ", ") + n + "=" +
             std::string(py::str(py::float_(slam3DParameterValue(s, n))));
      first = false;
    }
    return out + ")";
  });

  py::class_<Slam3D>(m, "Slam3D", R"doc(
3D LiDAR SLAM on an odometry's poses: every scan a node of an SE(3) pose graph, loop candidates
from a Scan Context descriptor of each node's local map (searched over every yaw, so revisits in
the opposite direction are found) and from a radius search around the estimate, verified by ICP
with overlap tests, optimised with Ceres (Huber loss on loops). Its calls hold the GIL: threads
sharing one Slam3D run one call at a time. A refused scan (a pose that is not rigid or beyond
1e6 m) leaves the object as it was.
)doc")
      .def(py::init([](std::optional<Slam3DConfig> config) {
             return std::make_unique<Slam3D>(config ? *config : Slam3DConfig{});
           }),
           py::arg("config") = py::none())
      .def(
          "add_scan",
          [](Slam3D& s, const py::object& points, const py::object& odometry_pose) {
            const pcl::PointCloud<pcl::PointXYZ> cloud = cloudFrom(points);
            Eigen::Isometry3d pose;
            pose.matrix() = matrix4From(odometry_pose, "odometry_pose");
            return reportDict(s.addScan(cloud, pose));
          },
          py::arg("points"), py::arg("odometry_pose"), R"doc(
Add the next scan.

Parameters
----------
points : array_like, shape (N, 3) or (N, 4)
    The scan in its sensor frame (NaN rows are skipped).
odometry_pose : array_like, shape (4, 4)
    Sensor -> odometry world.

Returns
-------
dict
    node, searched, candidates, verified, optimized.
)doc")
      .def(
          "finish", [](Slam3D& s) { return reportDict(s.finish()); },
          "Search the last nodes and optimise; call once after the last scan.")
      .def_property_readonly(
          "poses", [](const Slam3D& s) { return posesArray(s.poses()); },
          "(N, 4, 4) sensor -> map poses, current estimate.")
      .def_property_readonly(
          "odometry_poses", [](const Slam3D& s) { return posesArray(s.odometryPoses()); },
          "(N, 4, 4) the odometry's poses as given.")
      .def_property_readonly("loops", &loopsList,
                             "Every verified candidate: from, to, method, accepted, relation "
                             "(4x4, to -> from), overlap, structure_overlap, rmse, reason.")
      .def_property_readonly("verified_loops", &Slam3D::verifiedLoops)
      .def_property_readonly("timing", [](const Slam3D& s) { return timingDict(s.timing()); })
      .def_property_readonly("bytes", &Slam3D::bytes)
      .def("__len__", &Slam3D::size)
      .def(
          "local_map",
          [](const Slam3D& s, std::size_t i) {
            const std::vector<Eigen::Vector3f> pts = s.localMap(i);
            std::vector<float> flat;
            flat.reserve(pts.size() * 3);
            for (const auto& p : pts) flat.insert(flat.end(), {p.x(), p.y(), p.z()});
            return arrayFrom(flat, {py::ssize_t(pts.size()), 3});
          },
          py::arg("node"), "(M, 3) float32: node's local map in its frame.");

  m.def(
      "slam3d_parameters", [] { return parameterList(slam3DParameterSchema()); },
      "list[dict]: every Slam3DConfig parameter as the library declares it (name, kind, unit, "
      "rule, min, max, min_open, max_open, default, doc).");

  m.def(
      "run_slam3d",
      [](py::object source, py::object frames, std::optional<Slam3DConfig> config,
         py::object progress) {
        ProgressWatch watch(progress);
        py::object holder;
        PySource& s = sourceFrom(source, holder);
        Slam3DRunOptions options;
        if (config) options.slam = *config;
        if (!frames.is_none()) options.odometry.frames = framesFrom(frames, "frames");
        Slam3DRun run;
        {
          ObjectGuard guard(s.mutex, "ScanSource");
          py::gil_scoped_release release;
          run = runSlam3D(
              *s.source, options,
              [&watch](std::size_t done, std::size_t total, const Slam3D&) { watch(done, total); });
        }
        py::dict d;
        d["poses"] = posesArray(run.trajectory.poses);
        d["stamps"] = doublesArray(run.trajectory.stamps);
        d["odometry_poses"] = posesArray(run.odometry.poses);
        d["map_poses"] = posesArray(run.map_poses);
        std::vector<double> f(run.frames.begin(), run.frames.end());
        d["frames"] = arrayFrom(std::vector<long long>(run.frames.begin(), run.frames.end()),
                                {py::ssize_t(run.frames.size())});
        py::dict seconds;
        seconds["read"] = run.read_seconds;
        seconds["odometry"] = run.odometry_seconds;
        seconds["slam"] = run.slam_seconds;
        d["seconds"] = seconds;
        d["slam"] = py::cast(std::move(run.slam));
        return d;
      },
      py::arg("source"), py::arg("frames") = py::none(), py::arg("config") = py::none(),
      py::kw_only(), py::arg("progress") = py::none(), R"doc(
Run the LiDAR odometry and :class:`Slam3D` over a scan source, as `metricmap slam3d` does.

Parameters
----------
source : ScanSource or str or os.PathLike
frames : sequence of int, optional
    Strictly increasing scan indices (default: all).
config : Slam3DConfig, optional
progress : callable(done, total), optional, keyword-only
    Called at most every 20 ms and after the last scan; Ctrl-C raises KeyboardInterrupt.

Returns
-------
dict
    poses (N, 4, 4) in the source's pose convention, stamps (N,) (empty without stamps),
    odometry_poses, map_poses (sensor -> map world, for maps), frames, seconds, slam (the
    finished :class:`Slam3D`).
)doc");
}

}  // namespace metricmap::python
