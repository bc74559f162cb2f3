#include "metricmap/io/map_server_reader.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/image_decoders.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

constexpr std::uint64_t kMaxYamlBytes = 1 << 20;

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw InputError(file + ": " + what);
}

double number(const YAML::Node& root, const char* key, const std::string& file, bool required,
              double fallback) {
  const YAML::Node n = root[key];
  if (!n) {
    if (required) fail(file, std::string("missing '") + key + "'");
    return fallback;
  }
  double v = 0.0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    fail(file, std::string("'") + key + "' is not a number");
  }
  if (!std::isfinite(v)) fail(file, std::string("'") + key + "' is not finite");
  return v;
}

/// Binary PGM (P5), maxval 255, comments allowed in the header.
MapServerImage readPgm(const std::string& path) {
  requireRegularFile(path);
  const std::uint64_t size = std::filesystem::file_size(path);
  const std::string bytes = readRegularFile(path, size + 1);
  std::size_t at = 0;
  const auto token = [&]() {
    while (at < bytes.size()) {
      if (bytes[at] == '#') {
        while (at < bytes.size() && bytes[at] != '\n') ++at;
      } else if (std::isspace(static_cast<unsigned char>(bytes[at]))) {
        ++at;
      } else {
        break;
      }
    }
    const std::size_t begin = at;
    while (at < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
    return bytes.substr(begin, at - begin);
  };
  if (token() != "P5") fail(path, "not a binary PGM (P5)");
  long long w = 0, h = 0, maxval = 0;
  try {
    w = std::stoll(token());
    h = std::stoll(token());
    maxval = std::stoll(token());
  } catch (const std::exception&) {
    fail(path, "damaged PGM header");
  }
  if (w <= 0 || h <= 0 || w > (1 << 20) || h > (1 << 20)) fail(path, "bad PGM size");
  if (maxval != 255) fail(path, "PGM maxval must be 255, got " + std::to_string(maxval));
  ++at;  // one whitespace byte after maxval
  const auto pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
  if (bytes.size() < at || bytes.size() - at < pixels) {
    fail(path, "truncated PGM (" + std::to_string(w) + " x " + std::to_string(h) + " pixels)");
  }
  MapServerImage image;
  image.width = static_cast<int>(w);
  image.height = static_cast<int>(h);
  image.pixels.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                      bytes.begin() + static_cast<std::ptrdiff_t>(at + pixels));
  return image;
}

MapServerImage readPngGrey(const std::string& path) {
  const detail::DecodedImage png = detail::decodePng(path, detail::ImageWant::Rgb8);
  MapServerImage image;
  image.width = png.width;
  image.height = png.height;
  const std::size_t n = static_cast<std::size_t>(png.width) * static_cast<std::size_t>(png.height);
  image.pixels.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned sum = png.rgb[3 * i] + png.rgb[3 * i + 1] + png.rgb[3 * i + 2];
    image.pixels[i] = static_cast<std::uint8_t>(sum / 3);
  }
  return image;
}

}  // namespace

MapServerMap readMapServer(const std::string& yaml_path) {
  const std::string text = readRegularFile(yaml_path, kMaxYamlBytes);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    fail(yaml_path, std::string("not YAML (") + e.what() + ")");
  }
  if (!root.IsMap()) fail(yaml_path, "not a map_server YAML (no mapping)");
  if (!root["image"] || !root["image"].IsScalar()) fail(yaml_path, "missing 'image'");
  MapServerMap map;
  const double res = number(root, "resolution", yaml_path, true, 0.0);
  if (res <= 0.0) fail(yaml_path, "'resolution' must be > 0");
  map.negate = number(root, "negate", yaml_path, false, 0.0) != 0.0;
  map.occupied_thresh = number(root, "occupied_thresh", yaml_path, false, 0.65);
  map.free_thresh = number(root, "free_thresh", yaml_path, false, 0.196);
  for (double t : {map.occupied_thresh, map.free_thresh}) {
    if (t < 0.0 || t > 1.0) fail(yaml_path, "thresholds must lie in [0, 1]");
  }
  const YAML::Node origin = root["origin"];
  if (!origin || !origin.IsSequence() || origin.size() < 2 || origin.size() > 3)
    fail(yaml_path, "'origin' must be [x, y, yaw]");
  double o[3] = {0, 0, 0};
  for (std::size_t i = 0; i < origin.size(); ++i) {
    try {
      o[i] = origin[i].as<double>();
    } catch (const YAML::Exception&) {
      fail(yaml_path, "'origin' must be [x, y, yaw] numbers");
    }
    if (!std::isfinite(o[i])) fail(yaml_path, "'origin' is not finite");
  }
  if (o[2] != 0.0) fail(yaml_path, "a rotated map (origin yaw != 0) is not supported");
  MapServerMode mode = MapServerMode::Unstated;
  if (root["mode"]) {
    const std::string m = root["mode"].as<std::string>("");
    if (m == "trinary") {
      mode = MapServerMode::Trinary;
    } else if (m == "scale") {
      mode = MapServerMode::Scale;
    } else if (m == "raw") {
      mode = MapServerMode::Raw;
    } else {
      fail(yaml_path, "unknown 'mode' (trinary, scale, raw)");
    }
  }
  std::filesystem::path image_path(root["image"].as<std::string>());
  if (image_path.is_relative())
    image_path = std::filesystem::path(yaml_path).parent_path() / image_path;
  const std::string ext = image_path.extension().string();
  if (ext == ".png" || ext == ".PNG") {
    map.image = readPngGrey(image_path.string());
  } else {
    map.image = readPgm(image_path.string());
  }
  map.image.resolution = res;
  map.image.origin_x = o[0];
  map.image.origin_y = o[1];
  map.image.mode = mode;
  return map;
}

}  // namespace metricmap
