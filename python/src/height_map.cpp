// metricmap.HeightMap: the top-down map of point counts per (cell, height bin) of
// mapping/height_map.h, accumulated over frames, and the camera poses it takes.
#include <memory>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/mapping/floor_fit.h"
#include "metricmap/mapping/height_map.h"
#include "object_lock.h"

namespace metricmap::python {

namespace {

pcl::PointCloud<pcl::PointXYZ> cloudOf(const PointsArray& p) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.resize(p.span.size);
  for (std::size_t i = 0; i < p.span.size; ++i) {
    const float* q = p.span.at(i);
    cloud[i] = pcl::PointXYZ(q[0], q[1], q[2]);
  }
  cloud.is_dense = false;
  return cloud;
}

Eigen::Isometry3d isometryFrom(const py::handle& obj) {
  const Eigen::Matrix4d m = matrix4From(obj, "to_map");
  checkRigidTransform(m, "to_map");  // a rotation (det +1, not a reflection), 0 0 0 1
  Eigen::Isometry3d t;
  t.matrix() = m;
  return t;
}

/// metricmap.HeightMap: the map and the lock that serialises its calls.
struct PyHeightMap : HeightMap {
  using HeightMap::HeightMap;
  mutable ObjectMutex mutex;
};

}  // namespace

void initHeightMap(py::module_& m) {
  py::class_<PyHeightMap, std::shared_ptr<PyHeightMap>>(m, "HeightMap", R"doc(
Top-down map of point counts per (cell, height bin), accumulated over frames (the
`metricmap heightmap` map). Map frame: x right, y forward, z up, metres; map_size x map_size
cells centred on the origin, row 0 the far (forward) edge; height bins as np.digitize(z, z_bins).
)doc")
      .def(py::init([](double resolution, std::size_t map_size, std::vector<double> z_bins,
                       std::uint32_t obstacle_threshold) {
             HeightMapParams p;
             p.resolution = resolution;
             p.map_size = map_size;
             p.z_bins = std::move(z_bins);
             p.obstacle_threshold = obstacle_threshold;
             return std::make_shared<PyHeightMap>(p);
           }),
           py::arg("resolution") = 0.05, py::arg("map_size") = 480,
           py::arg("z_bins") = std::vector<double>{0.1, 1.0}, py::arg("obstacle_threshold") = 1,
           "resolution (m, > 0), map_size (cells per side), z_bins (>= 2 strictly increasing "
           "edges, m), obstacle_threshold (middle-bin count that marks an obstacle).")
      .def(
          "add_frame",
          [](PyHeightMap& self, ArrayLike points, ArrayLike to_map) {
            ObjectGuard guard(self.mutex, "HeightMap");
            PointsArray p = pointsFromArray(points, "points");
            const Eigen::Isometry3d t = isometryFrom(to_map);
            const pcl::PointCloud<pcl::PointXYZ> cloud = cloudOf(p);
            py::gil_scoped_release release;
            self.addFrame(cloud, t);
          },
          py::arg("points"), py::arg("to_map"), R"doc(
Add a frame's points (its own frame; counts add up over frames).

Parameters
----------
points : array_like, shape (N, 3) or (N, 4)
    Metres; an organized (H, W, 3) cloud goes in as ``cloud.reshape(-1, 3)``. NaN skipped.
to_map : array_like, shape (4, 4)
    Rigid transform of the points into the map frame (e.g. :func:`camera_to_map`).
)doc")
      .def_property_readonly(
          "counts",
          [](py::object self) {
            const auto& h = self.cast<const PyHeightMap&>();
            const py::ssize_t n = static_cast<py::ssize_t>(h.size());
            const py::ssize_t b = static_cast<py::ssize_t>(h.bins());
            const py::ssize_t s = sizeof(std::uint32_t);
            return viewOf<std::uint32_t>(h.counts().data(), {n, n, b}, {n * b * s, b * s, s}, self);
          },
          "(map_size, map_size, bins) uint32 read-only view: counts [row, col, bin]. It follows "
          "later frames (the map's own memory).")
      .def_property_readonly(
          "obstacles",
          [](const PyHeightMap& h) {
            ObjectGuard guard(h.mutex, "HeightMap");
            const py::ssize_t n = static_cast<py::ssize_t>(h.size());
            py::array_t<bool> a({n, n});
            auto r = a.mutable_unchecked<2>();
            for (py::ssize_t i = 0; i < n; ++i)
              for (py::ssize_t j = 0; j < n; ++j) r(i, j) = h.obstacle(i, j);
            return a;
          },
          "(map_size, map_size) bool: middle-bin count >= obstacle_threshold.")
      .def_property_readonly(
          "explored",
          [](const PyHeightMap& h) {
            ObjectGuard guard(h.mutex, "HeightMap");
            const py::ssize_t n = static_cast<py::ssize_t>(h.size());
            py::array_t<bool> a({n, n});
            auto r = a.mutable_unchecked<2>();
            for (py::ssize_t i = 0; i < n; ++i)
              for (py::ssize_t j = 0; j < n; ++j) r(i, j) = h.explored(i, j);
            return a;
          },
          "(map_size, map_size) bool: cells with any point.")
      .def_property_readonly(
          "statistics",
          [](const PyHeightMap& h) {
            ObjectGuard guard(h.mutex, "HeightMap");
            const HeightMapStatistics& s = h.statistics();
            py::dict d;
            d["bin_counts"] = s.bin_counts;
            d["points_outside_map"] = s.points_outside_map;
            d["valid_points"] = s.valid_points;
            d["frames"] = s.frames;
            d["obstacle_cells"] = h.obstacleCells();
            d["explored_cells"] = h.exploredCells();
            return d;
          },
          "dict: bin_counts, points_outside_map, valid_points, frames, obstacle_cells, "
          "explored_cells.");

  m.def(
      "camera_to_map",
      [](double height, double pitch, double yaw) {
        return matrix4(cameraToMap(height, pitch, yaw).matrix());
      },
      py::arg("height"), py::arg("pitch"), py::arg("yaw") = 0.0,
      "(4, 4) pose of a camera (optical frame: x right, y down, z forward) `height` metres above "
      "the floor, pitched down by `pitch` and turned left by `yaw` (radians), in the map frame.");

  m.def(
      "fit_floor",
      [](ArrayLike points, double distance_threshold, std::size_t stride) {
        PointsArray p = pointsFromArray(points, "points");
        const pcl::PointCloud<pcl::PointXYZ> cloud = cloudOf(p);
        FloorPlane f;
        {
          py::gil_scoped_release release;
          f = fitFloor(cloud, distance_threshold, stride);
        }
        return py::make_tuple(matrix4(cameraToMapFromFloor(f.normal, f.d).matrix()),
                              py::make_tuple(f.normal.x(), f.normal.y(), f.normal.z(), f.d),
                              f.inliers);
      },
      py::arg("points"), py::arg("distance_threshold") = 0.02, py::arg("stride") = 4, R"doc(
The floor of a camera-frame cloud by RANSAC (`--auto-floor`) and the camera pose it gives.

Returns
-------
(to_map (4, 4), (nx, ny, nz, d), inliers)
    The floor-aligned camera pose, the plane n.p + d = 0 (d = camera height) and its inliers.

Raises
------
InputError (a ValueError)
    no plane with at least 100 inliers.
)doc");
}

}  // namespace metricmap::python
