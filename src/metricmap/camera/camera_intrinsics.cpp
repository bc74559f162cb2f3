#include "metricmap/camera/camera_intrinsics.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <nlohmann/json.hpp>

#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

constexpr int kMaxNesting = 32;
constexpr std::size_t kMaxCameraFileBytes = 1 << 20;

/// A camera file is small: refuse special files, more than 1 MiB and NUL bytes before parsing.
std::string readSmallText(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path + ": cannot open (not a regular file)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  std::string text(kMaxCameraFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxCameraFileBytes)
    throw InputError(path + ": larger than 1 MiB, not a camera file");
  if (text.find('\0') != std::string::npos)
    throw InputError(path + ": holds NUL bytes, not a text file");
  // boost's XML parser recurses once per element: bound the nesting before it runs.
  int depth = 0, deepest = 0;
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] == '<' && text[i + 1] != '/' && text[i + 1] != '?' && text[i + 1] != '!')
      deepest = std::max(deepest, ++depth);
    if (text[i] == '<' && text[i + 1] == '/') --depth;
    if (text[i] == '/' && text[i + 1] == '>') --depth;
  }
  if (deepest > kMaxNesting) throw InputError(path + ": nested deeper than 32 levels");
  return text;
}

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return std::string();
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

}  // namespace

void validateIntrinsics(const CameraIntrinsics& k) {
  if (!(std::isfinite(k.fx) && k.fx > 0 && std::isfinite(k.fy) && k.fy > 0 && std::isfinite(k.cx) &&
        std::isfinite(k.cy))) {
    std::ostringstream os;
    os << "intrinsics need finite fx, fy > 0 and finite cx, cy; got " << k.fx << "," << k.fy << ","
       << k.cx << "," << k.cy;
    throw std::invalid_argument(os.str());
  }
  // Points are float: a focal length outside the float range would turn every coordinate
  // (x = (u - cx) z / fx) into inf, or 0.
  for (auto [value, name] : {std::pair{k.fx, "fx"}, std::pair{k.fy, "fy"}})
    if (beyondFloatRange(value) || belowFloatRange(value))
      throw std::invalid_argument("intrinsics: " + std::string(name) + " " + formatNumber(value) +
                                  " is outside the single-precision range (1.17549e-38 to "
                                  "3.40282e+38)");
}

CameraIntrinsics parseIntrinsics(const std::string& text) {
  const std::vector<double> v = parseDoubleList(text, "intrinsics");
  if (v.size() != 4) {
    throw std::invalid_argument("intrinsics must be 4 numbers fx,fy,cx,cy, got " +
                                std::to_string(v.size()) + " in '" + quoteForMessage(text) + "'");
  }
  CameraIntrinsics k;
  k.fx = v[0];
  k.fy = v[1];
  k.cx = v[2];
  k.cy = v[3];
  validateIntrinsics(k);
  return k;
}

CameraIntrinsics readPclGrabberXml(const std::string& path) {
  boost::property_tree::ptree tree;
  try {
    std::istringstream text(readSmallText(path));
    boost::property_tree::read_xml(text, tree);
    const boost::property_tree::ptree& d = tree.get_child("depth");
    const auto number = [&](const char* key) {
      return parseFiniteDouble(trimmed(d.get<std::string>(key)), key);
    };
    CameraIntrinsics k;
    k.fx = number("focal_length_x");
    k.fy = number("focal_length_y");
    k.cx = number("principal_point_x");
    k.cy = number("principal_point_y");
    if (d.get_child_optional("z_multiplication_factor")) {
      k.depth_scale = number("z_multiplication_factor");
      if (!(k.depth_scale > 0.0)) {
        throw std::invalid_argument("z_multiplication_factor must be > 0, got " +
                                    formatNumber(k.depth_scale));
      }
    }
    validateIntrinsics(k);
    return k;
  } catch (const std::exception& e) {
    throw InputError(path + ": not a PCL grabber camera XML with a <depth> block (" +
                     quoteForMessage(std::string(e.what()).substr(0, 120)) + ")");
  }
}

CameraIntrinsics readOpen3dJson(const std::string& path) {
  const std::string text = readSmallText(path);
  try {
    // Refuse deep nesting while parsing (nlohmann's parser and destructor recurse).
    const nlohmann::json j =
        nlohmann::json::parse(text, [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
          if (depth > kMaxNesting) throw std::invalid_argument("nested deeper than 32 levels");
          return true;
        });
    const auto& m = j.at("intrinsic_matrix");
    if (!m.is_array() || m.size() != 9)
      throw std::invalid_argument("intrinsic_matrix needs 9 numbers");
    CameraIntrinsics k;
    k.fx = m.at(0).get<double>();  // column-major 3x3
    k.fy = m.at(4).get<double>();
    k.cx = m.at(6).get<double>();
    k.cy = m.at(7).get<double>();
    for (int i : {0, 4, 6, 7}) {
      if (!m.at(i).is_number()) throw std::invalid_argument("intrinsic_matrix holds a non-number");
    }
    const auto size = [&](const char* key) {
      if (!j.contains(key)) return 0;
      const auto& v = j.at(key);
      if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > (1 << 20))
        throw std::invalid_argument(std::string(key) + " must be an integer in [0, 1048576]");
      return static_cast<int>(v.get<long long>());
    };
    k.width = size("width");
    k.height = size("height");
    validateIntrinsics(k);
    return k;
  } catch (const std::exception& e) {
    throw InputError(path + ": not an Open3D camera JSON (" +
                     quoteForMessage(std::string(e.what()).substr(0, 120)) + ")");
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
