// Reading and writing clouds: .pcd / .ply / KITTI .bin -> arrays (io/cloud_reader.h), PCD out.
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"

namespace metricmap::python {

namespace {

py::dtype dtypeOf(std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8:
      return py::dtype::of<std::int8_t>();
    case pcl::PCLPointField::UINT8:
      return py::dtype::of<std::uint8_t>();
    case pcl::PCLPointField::INT16:
      return py::dtype::of<std::int16_t>();
    case pcl::PCLPointField::UINT16:
      return py::dtype::of<std::uint16_t>();
    case pcl::PCLPointField::INT32:
      return py::dtype::of<std::int32_t>();
    case pcl::PCLPointField::UINT32:
      return py::dtype::of<std::uint32_t>();
    case pcl::PCLPointField::FLOAT32:
      return py::dtype::of<float>();
    case pcl::PCLPointField::FLOAT64:
      return py::dtype::of<double>();
    default:
      throw py::value_error("unsupported PCL field datatype " + std::to_string(datatype));
  }
}

py::dict reportDict(const LoadReport& r) {
  py::dict d;
  d["path"] = r.path;
  d["format"] = r.format;
  d["fields"] = r.fields;
  d["width"] = r.width;
  d["height"] = r.height;
  d["points_in_file"] = r.points_in_file;
  d["nonfinite_dropped"] = r.nonfinite_dropped;
  d["skipped_lines"] = r.skipped_lines;
  d["warnings"] = r.warnings;
  if (r.has_viewpoint)
    d["viewpoint"] = py::make_tuple(r.viewpoint[0], r.viewpoint[1], r.viewpoint[2], r.viewpoint[3],
                                    r.viewpoint[4], r.viewpoint[5], r.viewpoint[6]);
  else
    d["viewpoint"] = py::none();
  return d;
}

/// What the CLI prints as `warning: ...` about a file it read, as Python UserWarnings.
void warnAbout(const LoadReport& r) {
  for (const std::string& w : r.warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
}

}  // namespace

void initCloudIo(py::module_& m) {
  m.def(
      "read_points",
      [](const std::filesystem::path& path) {
        auto cloud = std::make_unique<pcl::PointCloud<pcl::PointXYZ>>();
        LoadReport report;
        {
          py::gil_scoped_release release;
          report = loadCloud(path.string(), *cloud);
        }
        warnAbout(report);
        const py::ssize_t n = static_cast<py::ssize_t>(cloud->size());
        float* data = n ? cloud->points[0].data : nullptr;
        // The array owns the cloud: (N, 4) float32 rows x, y, z, 1 — PCL's own memory.
        py::capsule owner(cloud.get(),
                          [](void* p) { delete static_cast<pcl::PointCloud<pcl::PointXYZ>*>(p); });
        cloud.release();
        if (n == 0) return py::array(py::dtype::of<float>(), std::vector<py::ssize_t>{0, 4});
        return py::array(py::dtype::of<float>(), {n, py::ssize_t(4)},
                         {py::ssize_t(sizeof(pcl::PointXYZ)), py::ssize_t(sizeof(float))}, data,
                         owner);
      },
      py::arg("path"), R"doc(
Read the finite points of a .pcd (ascii, binary, binary_compressed), .ply or KITTI .bin file.

Parameters
----------
path : str
    The file; the format is chosen by its extension.

Returns
-------
numpy.ndarray, shape (N, 4), float32
    x, y, z in metres and 1.0 (PCL's padding): the layout the kernels read fastest, so the
    array passes to :func:`grid` / :func:`octree` without a copy. Points with a NaN/Inf
    coordinate are dropped.

Raises
------
InputError (an OSError)
    missing, unreadable, malformed or truncated file, no x/y/z, no finite point.

Warns
-----
UserWarning
    what `metricmap` prints as a warning about the file (a PCD header with WIDTH 0 HEIGHT 0
    but POINTS n, skipped ASCII lines).
)doc");

  m.def(
      "read_cloud",
      [](const std::filesystem::path& path) {
        pcl::PCLPointCloud2 blob;
        LoadReport report;
        {
          py::gil_scoped_release release;
          report = loadCloudBlob(path.string(), blob);
        }
        warnAbout(report);
        const std::size_t n = std::size_t{blob.width} * blob.height;
        py::dict fields;
        for (const pcl::PCLPointField& f : blob.fields) {
          if (f.name == "_" || f.name.empty()) continue;  // PCD padding
          py::dtype dt = dtypeOf(f.datatype);
          const std::size_t item = static_cast<std::size_t>(dt.itemsize());
          const std::size_t count = f.count == 0 ? 1 : f.count;
          if (f.offset + item * count > blob.point_step)
            throw py::value_error(path.string() + ": field " + f.name + " lies outside the point");
          std::vector<py::ssize_t> shape{py::ssize_t(n)};
          if (count > 1) shape.push_back(py::ssize_t(count));
          py::array a(dt, shape);
          auto* out = static_cast<std::uint8_t*>(a.mutable_data());
          for (std::size_t i = 0; i < n; ++i)
            std::memcpy(out + i * item * count, blob.data.data() + i * blob.point_step + f.offset,
                        item * count);
          fields[py::str(f.name)] = a;
        }
        return fields;
      },
      py::arg("path"), R"doc(
Read every field of a .pcd, .ply or KITTI .bin file as it was stored.

Returns
-------
dict[str, numpy.ndarray]
    One array per field, in file order ("x", "y", "z", "intensity", "rgb", ...), each of
    shape (N,) (or (N, count) for multi-valued fields) in the field's own dtype. Every point
    of the file is kept, NaN ones included; N = width * height.

Raises
------
InputError (an OSError)
    as :func:`read_points`.

Warns
-----
UserWarning
    as :func:`read_points`.
)doc");

  m.def(
      "cloud_info",
      [](const std::filesystem::path& path) {
        LoadReport report;
        {
          py::gil_scoped_release release;
          pcl::PointCloud<pcl::PointXYZ> cloud;
          report = loadCloud(path.string(), cloud);
        }
        return reportDict(report);
      },
      py::arg("path"), R"doc(
What `metricmap info` reports about a cloud file.

Returns
-------
dict
    path, format, fields, width, height, points_in_file, nonfinite_dropped, skipped_lines,
    warnings, viewpoint (tx, ty, tz, qw, qx, qy, qz or None).
)doc");

  m.def(
      "write_pcd",
      [](const std::filesystem::path& path, ArrayLike points, const std::string& format) {
        const PcdFormat fmt = parsePcdFormat(format);
        PointsArray p = pointsFromArray(points, "points", true);
        if (p.span.size == 0)  // read_points and the CLI refuse a PCD that declares 0 points
          throw py::value_error("points is empty (0 points): a PCD file needs at least one point");
        pcl::PointCloud<pcl::PointXYZ> cloud;
        cloud.resize(p.span.size);
        for (std::size_t i = 0; i < p.span.size; ++i) {
          const float* q = p.span.at(i);
          cloud[i] = pcl::PointXYZ(q[0], q[1], q[2]);
        }
        cloud.width = static_cast<std::uint32_t>(cloud.size());
        cloud.height = 1;
        cloud.is_dense = false;
        try {
          py::gil_scoped_release release;
          savePcdAtomic(path.string(), cloud, fmt);
        } catch (const std::invalid_argument&) {
          throw;
        } catch (const std::runtime_error& e) {
          raiseOSError(e);
        }
      },
      py::arg("path"), py::arg("points"), py::arg("format") = "binary", R"doc(
Write x, y, z of points as a PCD file (written to a temporary file, then renamed).

Parameters
----------
path : str
points : array_like, shape (N, 3) or (N, 4)
    Metres; a fourth column is not written.
format : {'ascii', 'binary', 'binary_compressed'}

Raises
------
OSError
    the file cannot be written.
ValueError
    unknown format, wrong shape, no points (a PCD of 0 points is refused by the readers).
)doc");
}

}  // namespace metricmap::python
