#include "poses.h"

#include "metricmap/common/rigid_transform.h"

#include <cmath>
#include <string>

#include "metricmap/exceptions.h"
#include "metricmap/io/map_server.h"

namespace metricmap::python {

py::array_t<double> posesArray(const std::vector<Eigen::Isometry3d>& poses) {
  py::array_t<double> a({py::ssize_t(poses.size()), py::ssize_t(4), py::ssize_t(4)});
  double* d = a.mutable_data();
  for (std::size_t k = 0; k < poses.size(); ++k)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) d[16 * k + 4 * i + j] = poses[k].matrix()(i, j);
  return a;
}

std::vector<Eigen::Isometry3d> posesFrom(const py::handle& obj, const char* name,
                                         bool allow_empty) {
  auto a = doublesFromArray(obj, name);
  if (a.ndim() != 3 || a.shape(1) != 4 || a.shape(2) != 4)
    throw py::value_error(std::string(name) + " must have shape (N, 4, 4)");
  const std::size_t n = static_cast<std::size_t>(a.shape(0));
  if (n == 0 && !allow_empty) throw py::value_error(std::string(name) + " is empty");
  std::vector<Eigen::Isometry3d> out(n);
  const double* d = a.data();
  for (std::size_t k = 0; k < n; ++k) {
    Eigen::Matrix4d m;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) m(i, j) = d[16 * k + 4 * i + j];
    checkRigidTransform(m, std::string(name) + "[" + std::to_string(k) + "]");
    out[k].matrix() = m;
  }
  return out;
}

std::vector<Pose2D> planarPosesFrom(const py::handle& obj, const char* name, bool allow_single) {
  auto a = doublesFromArray(obj, name);
  const bool single = allow_single && a.ndim() == 1 && a.shape(0) == 3;
  if (!single && (a.ndim() != 2 || a.shape(1) != 3))
    throw py::value_error(std::string(name) + " must have shape (N, 3): x, y, theta");
  const std::size_t n = single ? 1 : static_cast<std::size_t>(a.shape(0));
  if (n == 0) throw py::value_error(std::string(name) + " is empty");
  std::vector<Pose2D> out(n);
  const double* d = a.data();
  for (std::size_t k = 0; k < n; ++k) {
    out[k] = Pose2D{d[3 * k], d[3 * k + 1], d[3 * k + 2]};
    if (!std::isfinite(out[k].x) || !std::isfinite(out[k].y) || !std::isfinite(out[k].theta))
      throw py::value_error(std::string(name) + "[" + std::to_string(k) + "] is not finite");
  }
  return out;
}

std::vector<Eigen::Isometry3d> spatialOrPlanarPosesFrom(const py::handle& obj, const char* name) {
  auto a = doublesFromArray(obj, name);
  if (a.ndim() == 2 && a.shape(1) == 3) {
    std::vector<Eigen::Isometry3d> out;
    for (const Pose2D& p : planarPosesFrom(a, name)) out.push_back(spatial(p));
    return out;
  }
  if (a.ndim() != 3 || a.shape(1) != 4 || a.shape(2) != 4)
    throw py::value_error(std::string(name) + " must have shape (N, 4, 4) or (N, 3) (x, y, theta)");
  return posesFrom(a, name);
}

std::vector<double> stampsFrom(const py::handle& obj, const char* name, std::size_t n) {
  auto a = doublesFromArray(obj, name);
  if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n)
    throw py::value_error(std::string(name) + " must have shape (" + std::to_string(n) +
                          ",), one stamp per pose");
  std::vector<double> out(a.data(), a.data() + n);
  for (double s : out)
    if (!std::isfinite(s)) throw py::value_error(std::string(name) + " must be finite");
  return out;
}

py::array_t<double> doublesArray(const std::vector<double>& values) {
  return arrayFrom(values, {py::ssize_t(values.size())});
}

py::array_t<double> poses2dArray(const std::vector<Pose2D>& poses) {
  py::array_t<double> a({py::ssize_t(poses.size()), py::ssize_t(3)});
  double* d = a.mutable_data();
  for (std::size_t k = 0; k < poses.size(); ++k) {
    d[3 * k] = poses[k].x;
    d[3 * k + 1] = poses[k].y;
    d[3 * k + 2] = poses[k].theta;
  }
  return a;
}

Pose2D pose2dFrom(const py::handle& obj, const char* name) {
  auto a = doublesFromArray(obj, name);
  if (a.ndim() == 2 && a.shape(0) == 4 && a.shape(1) == 4) {
    const Eigen::Matrix4d m = matrix4From(obj, name);
    checkRigidTransform(m, name);  // a reflection or a shear has no planar pose
    Eigen::Isometry3d t;
    t.matrix() = m;
    return planar(t);
  }
  if (a.ndim() != 1 || a.shape(0) != 3)
    throw py::value_error(std::string(name) + " must be (x, y, theta) or a (4, 4) transform");
  const Pose2D p{a.data()[0], a.data()[1], a.data()[2]};
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.theta))
    throw py::value_error(std::string(name) + " must be finite");
  return p;
}

Pose2D planar(const Eigen::Isometry3d& t) {
  return {t.translation().x(), t.translation().y(), std::atan2(t(1, 0), t(0, 0))};
}

Eigen::Isometry3d spatial(const Pose2D& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() << p.x, p.y, 0.0;
  t.linear() = Eigen::Matrix3d(Eigen::AngleAxisd(p.theta, Eigen::Vector3d::UnitZ()));
  return t;
}

std::vector<std::size_t> framesFrom(const py::object& obj, const char* name) {
  std::vector<std::size_t> out;
  if (obj.is_none()) return out;
  if (py::isinstance(obj, py::module_::import("collections.abc").attr("Set"))) {
    if (py::len(obj) == 0)
      throw py::value_error(std::string(name) +
                            " is empty: nothing to process (None selects every scan)");
    throw py::type_error(std::string(name) +
                         " must be ordered (a set has no order): give e.g. sorted(" + name + ")");
  }
  py::object seq = obj;
  // An iterator or generator is read once into a list; numpy would see one object.
  if (!py::isinstance<py::array>(obj) && !py::hasattr(obj, "__len__") &&
      py::hasattr(obj, "__iter__"))
    seq = py::list(obj);
  if (py::isinstance<py::str>(seq) || py::isinstance<py::bytes>(seq))
    throw py::type_error(std::string(name) + " must be a sequence of integers, got a string");
  py::array a = py::array::ensure(seq);
  if (!a) throw py::type_error(std::string(name) + " must be a sequence of integers");
  if (a.size() == 0)
    throw py::value_error(std::string(name) +
                          " is empty: nothing to process (None selects every scan)");
  if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw py::type_error(std::string(name) + " must hold integers");
  if (a.ndim() != 1) throw py::value_error(std::string(name) + " must be 1-D");
  auto v = py::array_t<long long, py::array::c_style | py::array::forcecast>(a);
  for (py::ssize_t k = 0; k < v.size(); ++k) {
    if (v.data()[k] < 0) throw py::value_error(std::string(name) + " must not be negative");
    out.push_back(static_cast<std::size_t>(v.data()[k]));
  }
  return out;
}

std::vector<std::size_t> selectedFrames(const py::object& frames, std::size_t size) {
  std::vector<std::size_t> f = framesFrom(frames, "frames");
  if (frames.is_none())
    for (std::size_t k = 0; k < size; ++k) f.push_back(k);
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (f[k] >= size)
      throw py::value_error("frame " + std::to_string(f[k]) + " is out of range (" +
                            std::to_string(size) + " scans)");
    if (k > 0 && f[k] <= f[k - 1]) throw py::value_error("frames must be strictly increasing");
  }
  return f;
}

py::dict mapServerDict(const MapServerImage& image) {
  py::dict d;
  py::array_t<std::uint8_t> a({py::ssize_t(image.height), py::ssize_t(image.width)});
  if (!image.pixels.empty()) std::copy(image.pixels.begin(), image.pixels.end(), a.mutable_data());
  d["image"] = a;
  d["resolution"] = image.resolution;
  d["origin"] = py::make_tuple(image.origin_x, image.origin_y);
  d["mode"] = image.mode == MapServerMode::Scale     ? "scale"
              : image.mode == MapServerMode::Trinary ? "trinary"
              : image.mode == MapServerMode::Raw     ? "raw"
                                                     : "unstated";
  return d;
}

void writeMapImage(const std::string& path, const MapServerImage& image) {
  if (path.size() < 4 || path.compare(path.size() - 4, 4, ".pgm") != 0)
    throw py::value_error(path + ": a map_server map must be written to a .pgm path");
  MapServerFiles files = mapServerFiles(path);
  files.preview_png.clear();
  files.heat_png.clear();
  try {
    py::gil_scoped_release release;
    writeMapServer(image, files);
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const InputError&) {
    throw;
  } catch (const CapacityError&) {
    throw;
  } catch (const std::runtime_error& e) {
    raiseOSError(e);
  }
}

}  // namespace metricmap::python
