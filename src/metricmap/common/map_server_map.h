#pragma once
/// \file map_server_map.h
/// \brief A map_server map as read back: its image and the YAML's interpretation of the pixels.

#include <cstdint>

#include "metricmap/common/map_server_image.h"

namespace metricmap {

/// \brief The image and the YAML's thresholds: a pixel's occupancy is p = (255 - v) / 255
/// (v / 255 when negated); occupied when p > occupied_thresh, free when p < free_thresh,
/// unknown between.
struct MapServerMap {
  MapServerImage image;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  bool negate = false;
};

/// \brief kMapOccupied, kMapFree or kMapUnknown for a pixel by map_server's rule; in raw mode
/// a pixel is a percentage (p = v / 100) and 255 is unknown.
inline std::uint8_t mapServerClass(const MapServerMap& map, std::uint8_t v) {
  if (map.image.mode == MapServerMode::Raw && v == 255) return kMapUnknown;
  const double p = map.image.mode == MapServerMode::Raw ? v / 100.0
                   : map.negate                         ? v / 255.0
                                                        : (255.0 - v) / 255.0;
  if (p > map.occupied_thresh) return kMapOccupied;
  if (p < map.free_thresh) return kMapFree;
  return kMapUnknown;
}

}  // namespace metricmap
