#include "metricmap/io/camera_intrinsics.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <nlohmann/json.hpp>

#include "metricmap/exceptions.h"

namespace metricmap {

void validateIntrinsics(const CameraIntrinsics& k) {
  if (!(std::isfinite(k.fx) && k.fx > 0 && std::isfinite(k.fy) && k.fy > 0 && std::isfinite(k.cx) &&
        std::isfinite(k.cy))) {
    std::ostringstream os;
    os << "intrinsics need finite fx, fy > 0 and finite cx, cy; got " << k.fx << "," << k.fy << ","
       << k.cx << "," << k.cy;
    throw std::invalid_argument(os.str());
  }
}

CameraIntrinsics parseIntrinsics(const std::string& text) {
  CameraIntrinsics k;
  double* fields[4] = {&k.fx, &k.fy, &k.cx, &k.cy};
  std::istringstream is(text);
  std::string item;
  int n = 0;
  for (; std::getline(is, item, ','); ++n) {
    char* end = nullptr;
    if (n >= 4) break;
    *fields[n] = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0')
      throw std::invalid_argument("intrinsics: '" + item + "' is not a number");
  }
  if (n != 4) throw std::invalid_argument("intrinsics must be fx,fy,cx,cy, got '" + text + "'");
  validateIntrinsics(k);
  return k;
}

CameraIntrinsics readPclGrabberXml(const std::string& path) {
  boost::property_tree::ptree tree;
  try {
    boost::property_tree::read_xml(path, tree);
    const boost::property_tree::ptree& d = tree.get_child("depth");
    CameraIntrinsics k;
    k.fx = d.get<double>("focal_length_x");
    k.fy = d.get<double>("focal_length_y");
    k.cx = d.get<double>("principal_point_x");
    k.cy = d.get<double>("principal_point_y");
    k.depth_scale = d.get<double>("z_multiplication_factor", 0.0);
    validateIntrinsics(k);
    return k;
  } catch (const std::exception& e) {
    throw InputError(path + ": not a PCL grabber camera XML with a <depth> block (" +
                     std::string(e.what()).substr(0, 80) + ")");
  }
}

CameraIntrinsics readOpen3dJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    const auto& m = j.at("intrinsic_matrix");
    if (!m.is_array() || m.size() != 9)
      throw std::invalid_argument("intrinsic_matrix needs 9 numbers");
    CameraIntrinsics k;
    k.fx = m.at(0).get<double>();  // column-major 3x3
    k.fy = m.at(4).get<double>();
    k.cx = m.at(6).get<double>();
    k.cy = m.at(7).get<double>();
    k.width = j.value("width", 0);
    k.height = j.value("height", 0);
    validateIntrinsics(k);
    return k;
  } catch (const std::exception& e) {
    throw InputError(path + ": not an Open3D camera JSON (" + std::string(e.what()).substr(0, 80) +
                     ")");
  }
}

CameraIntrinsics intrinsicsFromHfov(double hfov_deg, int width, int height) {
  if (!(hfov_deg > 0.0 && hfov_deg < 180.0)) {
    throw std::invalid_argument("horizontal field of view must be in (0, 180) degrees, got " +
                                std::to_string(hfov_deg));
  }
  CameraIntrinsics k;
  k.fx = k.fy = (width / 2.0) / std::tan(hfov_deg * M_PI / 360.0);
  k.cx = width / 2.0;
  k.cy = height / 2.0;
  k.width = width;
  k.height = height;
  return k;
}

CameraIntrinsics readCameraFile(const std::string& path) {
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  if (ext == "xml") return readPclGrabberXml(path);
  if (ext == "json") return readOpen3dJson(path);
  throw InputError(path + ": unknown camera file (expected PCL grabber .xml or Open3D .json)");
}

}  // namespace metricmap
