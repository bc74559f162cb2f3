#pragma once
/// \file map_picture.h
/// \brief A map_server image drawn in colour with a trajectory and links over it (a SLAM run's
/// picture: the path in blue, loop closures in red).

#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "metricmap/common/map_server_image.h"

namespace metricmap {

/// \brief RGB pixels (width x height x 3, row 0 at the top) of `map` at `scale` pixels per map
/// cell (1..8), with `path` (world x, y) as a blue polyline and `links` as red segments.
/// Points outside the image are clipped. \throws std::invalid_argument for an empty map or a
/// scale out of range
std::vector<std::uint8_t> drawMapPicture(
    const MapServerImage& map, int scale, const std::vector<Eigen::Vector2d>& path,
    const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& links);

}  // namespace metricmap
