// Depth images -> clouds (camera/depth_to_cloud.h) and camera intrinsics files.
#include <cstring>
#include <filesystem>
#include <string>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.h"
#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/io/depth_image.h"

namespace metricmap::python {

void initCamera(py::module_& m) {
  m.def(
      "read_depth_image",
      [](const std::filesystem::path& path) {
        DepthImage img;
        {
          py::gil_scoped_release release;
          img = readDepthImage(path.string());
        }
        py::array_t<std::uint16_t> a({py::ssize_t(img.height), py::ssize_t(img.width)});
        if (!img.values.empty())
          std::memcpy(a.mutable_data(), img.values.data(), img.values.size() * 2);
        return a;
      },
      py::arg("path"),
      "(H, W) uint16 raw depth of a 16-bit single-channel PNG or TIFF (0 = no measurement). "
      "Raises InputError (an OSError) for a bad file.");

  m.def(
      "read_camera",
      [](const std::filesystem::path& path) {
        const CameraIntrinsics k = readCameraFile(path.string());
        py::dict d;
        d["fx"] = k.fx;
        d["fy"] = k.fy;
        d["cx"] = k.cx;
        d["cy"] = k.cy;
        d["width"] = k.width;
        d["height"] = k.height;
        d["depth_scale"] = k.depth_scale;
        return d;
      },
      py::arg("path"),
      "Pinhole intrinsics of a PCL grabber .xml or Open3D .json file: dict fx, fy, cx, cy "
      "(pixels), width, height (0 when not given), depth_scale (metres per unit; 0 when not "
      "given).");

  m.def(
      "depth_to_cloud",
      [](ArrayLike depth, double fx, double fy, double cx, double cy, double depth_scale) {
        py::array d = py::isinstance<py::array>(depth)
                          ? py::reinterpret_borrow<py::array>(depth)
                          : py::array(py::module_::import("numpy").attr("asarray")(depth));
        if (!d.dtype().is(py::dtype::of<std::uint16_t>()))
          throw py::type_error("depth must be a uint16 array (raw depth units), got dtype " +
                               py::str(d.dtype()).cast<std::string>());
        if (d.ndim() != 2 || d.shape(0) == 0 || d.shape(1) == 0)
          throw py::value_error("depth must have shape (H, W) with H, W > 0");
        // priced before any copy: the image (2 bytes), the cloud (16) and the array (12) a pixel
        checkMemory(static_cast<std::uint64_t>(d.shape(0)) * static_cast<std::uint64_t>(d.shape(1)),
                    2 + 16 + 12,
                    "depth_to_cloud: a " + std::to_string(d.shape(1)) + " x " +
                        std::to_string(d.shape(0)) + " depth image");
        CArray<std::uint16_t> c(d);
        DepthImage img;
        img.height = static_cast<int>(c.shape(0));
        img.width = static_cast<int>(c.shape(1));
        img.values.assign(c.data(), c.data() + c.size());
        CameraIntrinsics k;
        k.fx = fx;
        k.fy = fy;
        k.cx = cx;
        k.cy = cy;
        py::array_t<float> out({c.shape(0), c.shape(1), py::ssize_t(3)});
        float* o = out.mutable_data();
        {
          py::gil_scoped_release release;
          const pcl::PointCloud<pcl::PointXYZ> cloud = depthToCloud(img, k, depth_scale);
          for (std::size_t i = 0; i < cloud.size(); ++i) {
            o[3 * i] = cloud[i].x;
            o[3 * i + 1] = cloud[i].y;
            o[3 * i + 2] = cloud[i].z;
          }
        }
        return out;
      },
      py::arg("depth"), py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"),
      py::arg("depth_scale"), R"doc(
Depth image -> organized cloud in the camera optical frame (x right, y down, z forward).

Parameters
----------
depth : numpy.ndarray, shape (H, W), uint16
    Raw depth; 0 = no measurement.
fx, fy, cx, cy : float
    Pinhole intrinsics, pixels.
depth_scale : float
    Metres per raw unit (> 0): 0.001 for PCL grabber TIFFs, 0.0002 for TUM PNGs.

Returns
-------
numpy.ndarray, shape (H, W, 3), float32
    z = d * depth_scale, x = (u - cx) z / fx, y = (v - cy) z / fy; NaN where d = 0.
)doc");
}

}  // namespace metricmap::python
