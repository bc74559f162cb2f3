#include "metricmap/io/map_server_reader.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include <yaml-cpp/yaml.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

/// A map_server YAML is a few lines; anything larger is not one.
constexpr std::uint64_t kMaxYamlBytes = 1u << 20;
/// Pixels per side at most (as libpng's limit in io/).
constexpr std::uint64_t kMaxSide = 1u << 20;
/// Cell edges a map file holds (as OctoMap files in the occupancy module): finer cells make
/// every search over the map (localisation's rotations, distance fields) unboundedly large.
constexpr double kMapMinResolution = 1e-4, kMapMaxResolution = 1e3;

const YAML::Node required(const YAML::Node& root, const char* key, const std::string& path) {
  const YAML::Node n = root[key];
  if (!n) throw InputError(path + ": no '" + key + "' key (map_server requires it)");
  return n;
}

double number(const YAML::Node& n, const std::string& what) {
  if (!n.IsScalar()) throw InputError(what + ": not a number");
  try {
    return parseFiniteDouble(n.Scalar(), what);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

/// The PGM header's next integer (whitespace and # comments skipped), or -1.
long long pnmField(const std::string& bytes, std::size_t& i) {
  while (i < bytes.size() &&
         (std::isspace(static_cast<unsigned char>(bytes[i])) || bytes[i] == '#')) {
    if (bytes[i] == '#') {
      while (i < bytes.size() && bytes[i] != '\n') ++i;
    } else {
      ++i;
    }
  }
  if (i >= bytes.size() || !std::isdigit(static_cast<unsigned char>(bytes[i]))) return -1;
  long long v = 0;
  while (i < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[i]))) {
    v = v * 10 + (bytes[i++] - '0');
    if (v > (1LL << 40)) return -1;
  }
  return v;
}

/// Binary (P5) or plain (P2) PGM, maxval <= 255, scaled to 0..255.
std::vector<std::uint8_t> decodePgm(const std::string& path, const std::string& bytes, int& width,
                                    int& height) {
  const bool binary = bytes[1] == '5';
  std::size_t i = 2;
  const long long w = pnmField(bytes, i), h = pnmField(bytes, i), maxval = pnmField(bytes, i);
  if (w <= 0 || h <= 0 || maxval <= 0)
    throw InputError(path + ": damaged PGM header (width, height, maxval)");
  if (maxval > 255)
    throw InputError(path + ": 16-bit PGM (maxval " + std::to_string(maxval) +
                     "); map_server maps are 8-bit");
  if (static_cast<std::uint64_t>(w) > kMaxSide || static_cast<std::uint64_t>(h) > kMaxSide)
    throw InputError(path + ": PGM of " + std::to_string(w) + " x " + std::to_string(h) +
                     " pixels, more than " + std::to_string(kMaxSide) + " a side");
  const std::uint64_t pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
  // Binary: one byte per pixel after one whitespace; plain: at least two characters each.
  const std::uint64_t available = bytes.size() - std::min(bytes.size(), i + 1);
  if (binary ? available < pixels : available / 2 + 1 < pixels)
    throw InputError(path + ": PGM declares " + std::to_string(w) + " x " + std::to_string(h) +
                     " pixels but holds only " + std::to_string(bytes.size()) + " bytes");
  checkMemory(pixels, 2, path + ": " + std::to_string(w) + " x " + std::to_string(h) + " pixels");
  std::vector<std::uint8_t> grey(static_cast<std::size_t>(pixels));
  if (binary) {
    if (i >= bytes.size() || !std::isspace(static_cast<unsigned char>(bytes[i])))
      throw InputError(path + ": damaged PGM header (no whitespace before the pixels)");
    std::memcpy(grey.data(), bytes.data() + i + 1, grey.size());
  } else {
    for (std::size_t k = 0; k < grey.size(); ++k) {
      const long long v = pnmField(bytes, i);
      if (v < 0) throw InputError(path + ": plain PGM ends at pixel " + std::to_string(k));
      if (v > maxval)
        throw InputError(path + ": pixel " + std::to_string(k) + " is " + std::to_string(v) +
                         ", above maxval " + std::to_string(maxval));
      grey[k] = static_cast<std::uint8_t>(v);
    }
  }
  if (maxval != 255)
    for (std::uint8_t& g : grey) g = static_cast<std::uint8_t>(std::min(255LL, g * 255 / maxval));
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return grey;
}

std::vector<std::uint8_t> decodeImage(const std::string& path, int& width, int& height) {
  std::string head(8, '\0');
  {
    std::ifstream in = openRegularFile(path);
    in.read(head.data(), 8);
    head.resize(static_cast<std::size_t>(in.gcount()));
  }
  if (head.size() >= 2 && head[0] == 'P' && (head[1] == '5' || head[1] == '2')) {
    // Read whole: its size is bounded by the budget before reading.
    const std::string bytes = readRegularFile(path, memoryBudget());
    return decodePgm(path, bytes, width, height);
  }
  throw InputError(path + ": not a PGM image (P5 or P2)");
}

}  // namespace

MapServerYaml readMapServerYaml(const std::string& path) {
  const std::string text = readRegularFile(path, kMaxYamlBytes);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(path + ": not YAML (" + e.msg + ", line " + std::to_string(e.mark.line + 1) +
                     ")");
  }
  if (!root.IsMap()) throw InputError(path + ": not a map_server YAML (no key: value map)");
  MapServerYaml y;
  try {
    const YAML::Node image = required(root, "image", path);
    if (!image.IsScalar() || image.Scalar().empty())
      throw InputError(path + ": 'image' is not a file name");
    y.image = image.Scalar();
    const auto slash = path.find_last_of('/');
    y.image_path = y.image[0] == '/' || slash == std::string::npos
                       ? y.image
                       : path.substr(0, slash + 1) + y.image;
    y.resolution = number(required(root, "resolution", path), path + ": resolution");
    if (!(y.resolution >= kMapMinResolution && y.resolution <= kMapMaxResolution))
      throw InputError(path + ": resolution " + quoteForMessage(root["resolution"].Scalar()) +
                       " must be in [0.0001, 1000] m (the cell edges a map file holds)");
    const YAML::Node origin = required(root, "origin", path);
    if (!origin.IsSequence() || origin.size() != 3)
      throw InputError(path + ": origin must be [x, y, yaw]");
    y.origin_x = number(origin[0], path + ": origin x");
    y.origin_y = number(origin[1], path + ": origin y");
    y.origin_yaw = number(origin[2], path + ": origin yaw");
    if (std::fabs(y.origin_x) > 1e9 || std::fabs(y.origin_y) > 1e9)
      throw InputError(path + ": origin beyond +-1e9 m");
    if (std::fabs(y.origin_yaw) > kMaxAngle)
      throw InputError(path + ": origin yaw " + quoteForMessage(origin[2].Scalar()) +
                       " is beyond +-1e6 rad");
    const YAML::Node negate = required(root, "negate", path);
    const std::string ns = negate.IsScalar() ? negate.Scalar() : "";
    if (ns == "0" || ns == "false")
      y.negate = false;
    else if (ns == "1" || ns == "true")
      y.negate = true;
    else
      throw InputError(path + ": negate must be 0 or 1, not " + quoteForMessage(ns));
    y.occupied_thresh = number(required(root, "occupied_thresh", path), path + ": occupied_thresh");
    y.free_thresh = number(required(root, "free_thresh", path), path + ": free_thresh");
    if (!(y.free_thresh >= 0 && y.free_thresh <= y.occupied_thresh && y.occupied_thresh <= 1))
      throw InputError(path + ": thresholds must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
    if (const YAML::Node mode = root["mode"]) {
      const std::string m = mode.IsScalar() ? mode.Scalar() : "";
      if (m == "trinary")
        y.mode = MapServerReadMode::Trinary;
      else if (m == "scale")
        y.mode = MapServerReadMode::Scale;
      else if (m == "raw")
        y.mode = MapServerReadMode::Raw;
      else
        throw InputError(path + ": mode must be trinary, scale or raw, not " + quoteForMessage(m));
    }
  } catch (const YAML::Exception& e) {
    throw InputError(path + ": " + e.msg);
  }
  return y;
}

Map2D mapFromGrey(const std::vector<std::uint8_t>& grey, int width, int height,
                  const MapServerYaml& y) {
  Map2D map;
  map.width = width;
  map.height = height;
  map.resolution = y.resolution;
  map.origin = {y.origin_x, y.origin_y, y.origin_yaw};
  map.cells.resize(grey.size());
  for (int row = 0; row < height; ++row) {
    const int j = height - 1 - row;
    for (int i = 0; i < width; ++i) {
      int g = grey[static_cast<std::size_t>(row) * width + i];
      if (y.negate) g = 255 - g;
      std::int8_t v;
      if (y.mode == MapServerReadMode::Raw) {
        v = g <= 100 ? static_cast<std::int8_t>(g) : kCellUnknown;
      } else {
        const double occ = (255.0 - g) / 255.0;
        if (occ > y.occupied_thresh)
          v = kCellOccupied;
        else if (occ < y.free_thresh)
          v = kCellFree;
        else if (y.mode == MapServerReadMode::Trinary)
          v = kCellUnknown;
        else if (y.occupied_thresh > y.free_thresh)
          v = static_cast<std::int8_t>(99.0 * (occ - y.free_thresh) /
                                       (y.occupied_thresh - y.free_thresh));
        else  // occ equals both thresholds
          v = 0;
      }
      map.cells[static_cast<std::size_t>(j) * width + i] = v;
    }
  }
  return map;
}

Map2D loadMapServer(const std::string& yaml_path) {
  const MapServerYaml y = readMapServerYaml(yaml_path);
  int width = 0, height = 0;
  std::vector<std::uint8_t> grey;
  try {
    grey = decodeImage(y.image_path, width, height);
  } catch (const InputError& e) {
    throw InputError(yaml_path + ": its image " + e.what());
  } catch (const CapacityError& e) {
    throw CapacityError(yaml_path + ": its image " + e.what());
  }
  return mapFromGrey(grey, width, height, y);
}

MapServerImage mapServerImage(const Map2D& map) {
  MapServerImage image;
  image.width = map.width;
  image.height = map.height;
  image.resolution = map.resolution;
  image.pixels.resize(map.cells.size());
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) {
      const int v = map.at(i, j);
      image.pixels[static_cast<std::size_t>(map.height - 1 - j) * map.width + i] =
          v < 0    ? kMapUnknown
          : v == 0 ? kMapFree
                   : static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - v / 100.0)));
    }
  return image;
}

}  // namespace metricmap
