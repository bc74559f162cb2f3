#pragma once
/// \file map_server_reader.h
/// \brief Loading a ROS map_server map (the YAML and the image it names) as a Map2D, with
/// map_server's rules: every pixel's occupancy occ = (255 - grey) / 255 (grey = 255 - grey when
/// `negate`), then occupied (100) above occupied_thresh, free (0) below free_thresh, and
/// between them unknown (-1, `mode: trinary`, the default) or 99 (occ - free) / (occupied -
/// free) (`mode: scale`); `mode: raw` keeps grey values 0..100 and makes the others unknown.
/// Image row 0 is the top of the map.

#include <cstdint>
#include <string>
#include <vector>

#include "metricmap/common/map_2d.h"
#include "metricmap/common/map_server_image.h"

namespace metricmap {

/// \brief map_server's modes.
enum class MapServerReadMode { Trinary, Scale, Raw };

/// \brief What a map_server YAML says.
struct MapServerYaml {
  std::string image;       ///< as written
  std::string image_path;  ///< resolved against the YAML's folder when relative
  double resolution = 0.0;
  double origin_x = 0.0, origin_y = 0.0, origin_yaw = 0.0;
  bool negate = false;
  double occupied_thresh = 0.65, free_thresh = 0.196;
  MapServerReadMode mode = MapServerReadMode::Trinary;
};

/// \brief Read and check the YAML: image, resolution (> 0), origin [x, y, yaw], negate (0 or 1),
/// occupied_thresh and free_thresh (0 <= free <= occupied <= 1) are required as map_server
/// requires them; mode is optional. \throws InputError "YAML: ..." naming the key
MapServerYaml readMapServerYaml(const std::string& yaml_path);

/// \brief The map: the YAML, then its image (binary or plain PGM with maxval <= 255). The image's
/// size is checked against the file and the memory budget before any cell is allocated. \throws
/// InputError naming the YAML (and the image) for anything unreadable; CapacityError when the map
/// does not fit in the memory budget
Map2D loadMapServer(const std::string& yaml_path);

/// \brief The cells a map_server image becomes (the rules above); `grey` row 0 at the top.
Map2D mapFromGrey(const std::vector<std::uint8_t>& grey, int width, int height,
                  const MapServerYaml& yaml);

/// \brief The grey image a Map2D is drawn as (map_server's values back: occupied 0, free 254,
/// unknown 205, a scale cell v as 255 (1 - v / 100)), with origin (0, 0): the grid frame.
MapServerImage mapServerImage(const Map2D& map);

}  // namespace metricmap
