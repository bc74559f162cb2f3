#pragma once
/// \file map_places_3d.h
/// \brief Candidate places of a 3D map for the global search: the cells of a regular x/y grid
/// whose ground the map shows and that are free of map points to some height (where a robot
/// can stand), each with the descriptor of the map seen from there.
///
/// The map is first reduced to a height image (per cell: lowest and highest point). A place's
/// ground is the median of the lowest points of its cells; it needs place_min_ground_points map
/// points within 0.3 m above that ground, and at most 2 % of that count (or 2) between 0.5 m and
/// place_clearance above it. Its descriptor is made of the height image's cells within the
/// descriptor's radius, each at its highest point above the place's ground.

#include <vector>

#include <Eigen/Core>

#include "metricmap/localization/localizer_3d_config.h"
#include "metricmap/localization/point_map_3d.h"
#include "metricmap/slam3d/scan_context.h"

namespace metricmap {

struct MapPlace3D {
  Eigen::Vector3d position;  ///< x, y of the cell's centre; z of its ground
  ScanContext descriptor;
};

/// \brief The places of `map` (config: place_*, clip_*, descriptor).
/// \throws CapacityError when the height image does not fit the memory budget
std::vector<MapPlace3D> buildMapPlaces(const PointMap3D& map, const Localizer3DConfig& config);

}  // namespace metricmap
