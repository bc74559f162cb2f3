#pragma once
/// \file map_server_reader.h
/// \brief Read a map_server map: the YAML and the PGM or PNG image it names.

#include <string>

#include "metricmap/common/map_server_map.h"

namespace metricmap {

/// \brief Read `yaml_path` (image, resolution, origin [x, y, yaw], negate, occupied_thresh,
/// free_thresh, optional mode) and its image (binary PGM with maxval 255, or PNG, colour
/// averaged to grey), relative to the YAML's directory.
/// \throws InputError naming the file and the field (missing, not a number, resolution <= 0,
/// thresholds outside [0, 1], a non-zero yaw, an unreadable or truncated image); CapacityError
/// when the image does not fit the memory budget
MapServerMap readMapServer(const std::string& yaml_path);

}  // namespace metricmap
