#pragma once
/// \file inflation_costmap.h
/// \brief A 2D costmap as nav2's inflation layer defines it, from a 2D distance field.

#include <cstdint>

#include "metricmap/common/map_server_image.h"
#include "metricmap/distance/distance_field.h"

namespace metricmap {

/// \brief nav2_costmap_2d's cost values.
constexpr std::uint8_t kCostFree = 0, kCostInscribed = 253, kCostLethal = 254, kCostUnknown = 255;

/// \brief The inflation layer's parameters (nav2's names and defaults).
struct InflationParams {
  double inscribed_radius = 0.1;      ///< metres (the robot's; nav2 takes it from the footprint)
  double inflation_radius = 0.55;     ///< metres; cells farther are not inflated
  double cost_scaling_factor = 10.0;  ///< per metre
  bool inflate_unknown = false;       ///< unknown cells take any inflated cost, not only >= 253
};

/// \brief The cost of a cell `cells` cell edges from the nearest lethal cell (nav2's
/// computeCost, d = cells * resolution): 254 at 0, 253 while d <= the inscribed radius, then
/// floor(252 exp(-cost_scaling_factor (d - inscribed))), 0 beyond ceil(inflation_radius /
/// resolution) cells.
std::uint8_t inflationCost(double cells, double resolution, const InflationParams& params);

/// \brief The costmap of a 2D unsigned field with unknown as free (obstacles = occupied cells):
/// each known cell's inflationCost; an unknown cell stays 255 unless its cost is >= 253 (any
/// cost > 0 with inflate_unknown), as nav2's layer updates a master grid of unknown cells.
/// As a map_server image in raw mode (pixel = cost, row 0 at the top).
/// \throws std::invalid_argument for a 3D or signed field, unknown as occupied, a max_distance
/// below the inflation reach, or bad parameters (negative, NaN, inscribed > inflation radius)
MapServerImage inflationCostmap(const DistanceField& field, const InflationParams& params);

/// \brief The max_distance a field needs for inflationCostmap: the inflation reach plus a cell.
double inflationReach(double resolution, const InflationParams& params);

}  // namespace metricmap
