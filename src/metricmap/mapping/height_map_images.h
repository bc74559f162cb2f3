#pragma once
/// \file height_map_images.h
/// \brief The pictures of a height map: obstacles, explored cells and the dominant layer per cell.

#include <cstdint>
#include <vector>

namespace metricmap {

class HeightMap;

/// \brief Row-major pictures of map.size() x map.size() pixels.
struct HeightMapImages {
  std::vector<std::uint8_t> obstacles;  ///< grey: 0 for an obstacle, 255 elsewhere
  std::vector<std::uint8_t> explored;   ///< grey: 255 for an explored cell, 0 elsewhere
  /// RGB: each cell in the colour of its bin with the most points (low bins blue, the middle
  /// one red, higher ones yellow, green, ...), black for a cell without points.
  std::vector<std::uint8_t> layers;
};

/// \brief The three pictures of `map`.
HeightMapImages heightMapImages(const HeightMap& map);

}  // namespace metricmap
