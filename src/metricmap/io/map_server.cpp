#include "metricmap/io/map_server.h"

#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "metricmap/io/array_writers.h"
#include "metricmap/io/cloud_writer.h"

namespace metricmap {

MapServerFiles mapServerFiles(const std::string& pgm_path) {
  const auto dot = pgm_path.find_last_of('.'), slash = pgm_path.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = has_ext ? pgm_path.substr(0, dot) : pgm_path;
  const std::string name = slash == std::string::npos ? pgm_path : pgm_path.substr(slash + 1);
  return {pgm_path, stem + ".yaml", stem + "_preview.png", stem + "_heat.png", name};
}

void writeMapServer(const MapServerImage& image, const MapServerFiles& files,
                    const std::vector<std::uint8_t>& heat_rgb) {
  if (image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("the map is empty: no cell to write to " + files.pgm);
  if (image.pixels.size() !=
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("map image pixel count does not match its size");
  if (!heat_rgb.empty() && heat_rgb.size() != 3 * image.pixels.size())
    throw std::invalid_argument("map heat image size does not match the map's");
  YAML::Emitter yaml;
  yaml.SetDoublePrecision(10);
  yaml << YAML::BeginMap << YAML::Key << "image" << YAML::Value << files.image_name;
  if (image.mode != MapServerMode::Unstated)
    yaml << YAML::Key << "mode" << YAML::Value
         << (image.mode == MapServerMode::Trinary ? "trinary"
             : image.mode == MapServerMode::Scale ? "scale"
                                                  : "raw");
  yaml << YAML::Key << "resolution" << YAML::Value << image.resolution << YAML::Key << "origin"
       << YAML::Value << YAML::Flow << YAML::BeginSeq << image.origin_x << image.origin_y << 0.0
       << YAML::EndSeq << YAML::Key << "negate" << YAML::Value << 0 << YAML::Key
       << "occupied_thresh" << YAML::Value << 0.65 << YAML::Key << "free_thresh" << YAML::Value
       << 0.196 << YAML::EndMap;
  writePgm(files.pgm, image.width, image.height, image.pixels);
  writeTextAtomic(files.yaml, std::string(yaml.c_str()) + "\n");
  if (!files.preview_png.empty())
    writePng(files.preview_png, image.width, image.height, 1, image.pixels);
  if (!files.heat_png.empty() && !heat_rgb.empty())
    writePng(files.heat_png, image.width, image.height, 3, heat_rgb);
}

void writeMapServer(const MapServerImage& image, MapServerFiles files, OutputSet& outputs,
                    const std::vector<std::uint8_t>& heat_rgb) {
  if (heat_rgb.empty()) files.heat_png.clear();
  for (std::string* path : {&files.pgm, &files.yaml, &files.preview_png, &files.heat_png})
    if (!path->empty()) *path = outputs.stage(*path);
  writeMapServer(image, files, heat_rgb);
}

}  // namespace metricmap
