#pragma once
/// \file map_server_image.h
/// \brief A map as ROS map_server reads it: an 8-bit grey image with its resolution, origin and
/// mode. The maps make these (mapping/, occupancy/); io/map_server.h writes them.

#include <cstdint>
#include <vector>

namespace metricmap {

/// \brief map_server's trinary values: occupied (black), free (white), unknown.
constexpr std::uint8_t kMapOccupied = 0, kMapFree = 254, kMapUnknown = 205;

/// \brief The YAML's `mode`: not written (map_server's default, trinary), `trinary`,
/// `scale` (each pixel a probability: p = (255 - value) / 255), or `raw` (each pixel the cell's
/// value as is: costmaps, 255 unknown).
enum class MapServerMode { Unstated, Trinary, Scale, Raw };

/// \brief A grey image in map_server's convention: row 0 at the top; origin is the world
/// (x, y) of the lower-left corner of the lower-left pixel.
struct MapServerImage {
  int width = 0, height = 0;
  double resolution = 0.0, origin_x = 0.0, origin_y = 0.0;
  std::vector<std::uint8_t> pixels;  ///< row-major, 0 = occupied (black), 254 = free
  MapServerMode mode = MapServerMode::Unstated;
};

}  // namespace metricmap
