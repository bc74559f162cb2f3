#include "metricmap/distance/inflation_costmap.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace metricmap {
namespace {

void validate(const InflationParams& p) {
  const auto bad = [](double v) { return !std::isfinite(v) || v < 0.0; };
  std::ostringstream msg;
  if (bad(p.inscribed_radius))
    msg << "inscribed radius must be finite and >= 0, got " << p.inscribed_radius;
  else if (bad(p.inflation_radius))
    msg << "inflation radius must be finite and >= 0, got " << p.inflation_radius;
  else if (bad(p.cost_scaling_factor))
    msg << "cost scaling factor must be finite and >= 0, got " << p.cost_scaling_factor;
  else if (p.inscribed_radius > p.inflation_radius)
    msg << "inscribed radius " << p.inscribed_radius << " exceeds the inflation radius "
        << p.inflation_radius;
  if (!msg.str().empty()) throw std::invalid_argument(msg.str());
}

double reachCells(double resolution, const InflationParams& p) {
  return std::ceil(p.inflation_radius / resolution);
}

}  // namespace

std::uint8_t inflationCost(double cells, double resolution, const InflationParams& p) {
  if (cells > reachCells(resolution, p)) return kCostFree;
  if (cells == 0.0) return kCostLethal;
  const double distance = cells * resolution;
  if (distance <= p.inscribed_radius) return kCostInscribed;
  const double factor = std::exp(-1.0 * p.cost_scaling_factor * (distance - p.inscribed_radius));
  return static_cast<std::uint8_t>((kCostInscribed - 1) * factor);
}

double inflationReach(double resolution, const InflationParams& p) {
  return (reachCells(resolution, p) + 1.0) * resolution;
}

MapServerImage inflationCostmap(const DistanceField& field, const InflationParams& params) {
  validate(params);
  const DistanceFieldParams& fp = field.params();
  if (field.dimensions() != 2 || fp.signed_distance || fp.unknown != UnknownAs::Free)
    throw std::invalid_argument(
        "an inflation costmap needs a 2D unsigned field with unknown space as free");
  const double res = field.resolution();
  if (fp.max_distance < inflationReach(res, params)) {
    std::ostringstream msg;
    msg << "an inflation costmap of radius " << params.inflation_radius << " m needs a field up to "
        << inflationReach(res, params) << " m, this one stops at " << fp.max_distance << " m";
    throw std::invalid_argument(msg.str());
  }
  const std::size_t w = field.shape()[0], h = field.shape()[1];
  MapServerImage im;
  im.width = static_cast<int>(w);
  im.height = static_cast<int>(h);
  im.resolution = res;
  im.origin_x = field.origin().x() - 0.5 * res;
  im.origin_y = field.origin().y() - 0.5 * res;
  im.mode = MapServerMode::Raw;
  im.pixels.resize(w * h);
  for (std::size_t i = 0; i < w; ++i) {
    for (std::size_t j = 0; j < h; ++j) {
      // the field's float distance is sqrt(d2) * res rounded once: recover d2 exactly
      const double d2 = std::round(std::pow(static_cast<double>(field.at(i, j, 0)) / res, 2.0));
      std::uint8_t cost = field.at(i, j, 0) >= fp.max_distance
                              ? kCostFree
                              : inflationCost(std::sqrt(d2), res, params);
      if (field.states()[i * h + j] == kVoxelUnknown) {
        const bool take = params.inflate_unknown ? cost > kCostFree : cost >= kCostInscribed;
        if (!take) cost = kCostUnknown;
      }
      im.pixels[(h - 1 - j) * w + i] = cost;
    }
  }
  return im;
}

}  // namespace metricmap
