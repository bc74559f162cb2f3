#pragma once
/// \file map_server.h
/// \brief ROS map_server maps: a PGM image and the YAML that describes it.

#include <cstdint>
#include <string>
#include <vector>

namespace metricmap {

/// \brief A grey image in map_server's convention: row 0 at the top; origin is the world
/// (x, y) of the lower-left corner of the lower-left pixel.
struct MapServerImage {
  int width = 0, height = 0;
  double resolution = 0.0, origin_x = 0.0, origin_y = 0.0;
  std::vector<std::uint8_t> pixels;  ///< row-major, 0 = occupied (black), 254 = free
  bool trinary = false;              ///< YAML `mode: trinary` (205 = unknown)
};

/// \brief The files of a map_server map: PGM, YAML beside it, and optional PNG preview and
/// heat map; `image_name` is what the YAML's `image:` names (the PGM's final file name).
struct MapServerFiles {
  std::string pgm, yaml, preview_png, heat_png, image_name;
};

/// \brief M.pgm -> M.pgm, M.yaml, M_preview.png, M_heat.png, image "M.pgm" (without a
/// directory).
MapServerFiles mapServerFiles(const std::string& pgm_path);

/// \brief Write the PGM (P5), the YAML (image, [mode trinary,] resolution, origin [x, y, 0],
/// negate 0, occupied_thresh 0.65, free_thresh 0.196) and the PNG preview when its path is not
/// empty; `files.heat_png` is not written here. Each file through a temporary name and a rename.
/// \throws std::invalid_argument for an empty image or a pixel count that is not width x height
void writeMapServer(const MapServerImage& image, const MapServerFiles& files);

}  // namespace metricmap
