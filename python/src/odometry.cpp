// metricmap.LidarOdometry: scans in, poses out (registration/lidar_odometry.h), and the
// sensor profile that picks its range window and voxel from the first scan.
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/registration/lidar_odometry_config.h"
#include "metricmap/sequence/sensor_profile.h"
#include "object_lock.h"

namespace metricmap::python {

namespace {

std::vector<Eigen::Vector3d> points3d(const py::handle& obj) {
  PointsArray p = pointsFromArray(obj, "points", true);
  std::vector<Eigen::Vector3d> out(p.span.size);
  for (std::size_t i = 0; i < p.span.size; ++i) {
    const float* q = p.span.at(i);
    out[i] = Eigen::Vector3d(q[0], q[1], q[2]);
  }
  return out;
}

py::dict resultDict(const OdometryResult& r) {
  py::dict d;
  d["pose"] = matrix4(r.pose.matrix());
  d["prediction"] = matrix4(r.prediction.matrix());
  d["points_in"] = r.points_in;
  d["points_used"] = r.points_used;
  d["points_source"] = r.points_source;
  d["correspondences"] = r.correspondences;
  d["iterations"] = r.iterations;
  d["threshold"] = r.threshold;
  d["degenerate_directions"] = r.degenerate_directions;
  d["restarted"] = r.restarted;
  return d;
}

/// The Python object: the odometry and the report of its last frame.
struct PyOdometry {
  LidarOdometry odometry;
  OdometryResult last;
  mutable ObjectMutex mutex;  ///< serialises the object's calls
};

}  // namespace

void initOdometry(py::module_& m) {
  m.def(
      "sensor_profile",
      [](ArrayLike points, bool statistics) {
        const SensorProfile p = profileScan(points3d(points));
        py::dict d;
        if (statistics) {
          d["median_range"] = p.median_range;
          d["p995_range"] = p.p995_range;
        }
        d["max_range"] = p.max_range;
        d["min_range"] = p.min_range;
        d["voxel_size"] = p.voxel_size;
        d["coarse_voxel_size"] = p.coarse_voxel_size;
        d["max_threshold"] = p.max_threshold;
        d["convergence"] = p.convergence > 0.0 ? p.convergence : LidarOdometryConfig{}.convergence;
        return d;
      },
      py::arg("points"), py::kw_only(), py::arg("statistics") = false, R"doc(
The range window and voxel `metricmap odometry` picks from a first scan (sequence/sensor_profile),
as keyword arguments of :class:`LidarOdometry`: ``LidarOdometry(**sensor_profile(points))``.

Parameters
----------
points : array_like, shape (N, 3) or (N, 4)
statistics : bool
    Also give the scan's median_range and p995_range (m), the figures the choice is made from
    (then the dict is no longer only LidarOdometry's arguments).

Returns
-------
dict
    max_range, min_range, voxel_size, coarse_voxel_size, max_threshold, convergence (the
    LidarOdometry default where the profile leaves it).

Raises
------
ValueError
    fewer than 100 finite points at a range > 0.
)doc");

  py::class_<PyOdometry>(m, "LidarOdometry", R"doc(
LiDAR odometry from scans alone (KISS-ICP's method): robust point-to-point ICP of each scan
against a voxel-hashed local map, constant-velocity prediction, adaptive threshold. Give the
scans in acquisition order, each in its sensor frame; the first scan's frame is the world.
)doc")
      .def(py::init([](double max_range, double min_range, double voxel_size,
                       int max_points_per_voxel, double initial_threshold, double min_threshold,
                       double fine_threshold, int max_iterations, double convergence,
                       double max_threshold, double coarse_voxel_size, bool deskew,
                       unsigned threads) {
             LidarOdometryConfig c;
             c.max_range = max_range;
             c.min_range = min_range;
             c.voxel_size = voxel_size;
             c.max_points_per_voxel = max_points_per_voxel;
             c.initial_threshold = initial_threshold;
             c.min_threshold = min_threshold;
             c.fine_threshold = fine_threshold;
             c.max_iterations = max_iterations;
             c.convergence = convergence;
             c.max_threshold = max_threshold;
             c.coarse_voxel_size = coarse_voxel_size;
             c.deskew = deskew;
             c.threads = threads;
             return new PyOdometry{LidarOdometry(c), {}};
           }),
           py::arg("max_range") = 100.0, py::arg("min_range") = 3.0, py::arg("voxel_size") = 1.0,
           py::arg("max_points_per_voxel") = 20, py::arg("initial_threshold") = 2.0,
           py::arg("min_threshold") = 0.3, py::arg("fine_threshold") = 1.0,
           py::arg("max_iterations") = 500, py::arg("convergence") = 1e-4,
           py::arg("max_threshold") = 0.0, py::arg("coarse_voxel_size") = 0.0,
           py::arg("deskew") = false, py::arg("threads") = 0u,
           "Parameters as LidarOdometryConfig (metres); raises ValueError naming a bad one.")
      .def(
          "register_frame",
          [](PyOdometry& self, ArrayLike points, std::optional<ArrayLike> timestamps) {
            ObjectGuard guard(self.mutex, "LidarOdometry");
            std::vector<Eigen::Vector3d> p = points3d(points);
            std::vector<double> t;
            if (timestamps) {
              if (!self.odometry.config().deskew)
                throw py::value_error(
                    "timestamps are used only by deskew: give deskew=True, or no timestamps");
              auto a = doublesFromArray(*timestamps, "timestamps");
              if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != p.size())
                throw py::value_error("timestamps must have shape (N,), one per point");
              t.assign(a.data(), a.data() + a.size());
            }
            {
              py::gil_scoped_release release;
              self.last = self.odometry.registerFrame(p, t);
            }
            return matrix4(self.last.pose.matrix());
          },
          py::arg("points"), py::arg("timestamps") = py::none(), R"doc(
Register the next scan and return its pose.

Parameters
----------
points : array_like, shape (N, 3) or (N, 4)
    The scan in its sensor frame, metres; NaN/Inf points are skipped.
timestamps : array_like, shape (N,), optional
    Per-point sweep times in [0, 1] (fractions of the frame period), for deskew: only with
    ``deskew=True``; finite wherever the point is.

Returns
-------
numpy.ndarray, shape (4, 4), float64
    Sensor -> first sensor frame.

Raises
------
InputError (a ValueError)
    empty scan, no finite point or none in range, or too few point pairs.
ValueError
    timestamps without deskew, of another length, or not finite where the point is.
RuntimeError
    called from within its own call (the object serialises calls from several threads).
)doc")
      .def_property_readonly(
          "last_result",
          [](const PyOdometry& self) {
            ObjectGuard guard(self.mutex, "LidarOdometry");
            if (self.odometry.poses().empty())
              throw py::value_error("no frame yet: call register_frame(points) first");
            return resultDict(self.last);
          },
          "dict: what registering the last frame gave (pose, prediction, points_in, "
          "points_used, points_source, correspondences, iterations, threshold, ...); "
          "ValueError before the first frame (and after reset).")
      .def_property_readonly(
          "poses",
          [](const PyOdometry& self) {
            ObjectGuard guard(self.mutex, "LidarOdometry");
            const auto& poses = self.odometry.poses();
            py::array_t<double> a({py::ssize_t(poses.size()), py::ssize_t(4), py::ssize_t(4)});
            double* d = a.mutable_data();
            for (std::size_t k = 0; k < poses.size(); ++k)
              for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) d[16 * k + 4 * i + j] = poses[k].matrix()(i, j);
            return a;
          },
          "(K, 4, 4) float64: every registered scan's pose.")
      .def(
          "reset",
          [](PyOdometry& self) {
            ObjectGuard guard(self.mutex, "LidarOdometry");
            self.odometry.reset();
          },
          "Forget every scan: the next becomes the world again.")
      .def("__repr__", [](const PyOdometry& self) {
        ObjectGuard guard(self.mutex, "LidarOdometry");
        const LidarOdometryConfig& c = self.odometry.config();
        const auto num = [](double v) { return py::repr(py::float_(v)).cast<std::string>(); };
        return "<metricmap.LidarOdometry max_range=" + num(c.max_range) +
               " min_range=" + num(c.min_range) + " voxel_size=" + num(c.voxel_size) +
               " coarse_voxel_size=" + num(c.coarse_voxel_size) +
               " max_threshold=" + num(c.max_threshold) + " convergence=" + num(c.convergence) +
               " deskew=" + (c.deskew ? "True" : "False") + ", " +
               std::to_string(self.odometry.poses().size()) + " scans registered>";
      });
}

}  // namespace metricmap::python
