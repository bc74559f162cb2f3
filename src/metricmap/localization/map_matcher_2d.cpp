#include "metricmap/localization/map_matcher_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/occupancy/log_odds_params.h"

namespace metricmap {

MapMatcher2D::MapMatcher2D(const Map2D& map, double occupied, double free, int depth, int coarse)
    : width_(map.width), height_(map.height), coarse_(coarse), resolution_(map.resolution) {
  if (coarse < 1 || coarse > 64)
    throw std::invalid_argument("the search's coarsening must be in 1..64");
  if (map.width <= 0 || map.height <= 0 ||
      map.cells.size() != static_cast<std::size_t>(map.width) * map.height)
    throw std::invalid_argument("the map has no cells");
  if (!(map.resolution > 0)) throw std::invalid_argument("the map's resolution must be > 0");
  checkMemory(map.cells.size(), sizeof(float), "the localisation grid of the map");
  LogOddsParams params;
  params.clamp_min = free;
  params.clamp_max = occupied;
  table_ = std::make_unique<ProbabilityTable>(params);
  const float lo = logOddsOf(free), hi = logOddsOf(occupied);
  log_odds_.resize(map.cells.size());
  occupied_.resize(map.cells.size());
  for (std::size_t k = 0; k < map.cells.size(); ++k) {
    const int v = map.cells[k];
    occupied_[k] = v >= 100 ? 1 : 0;
    if (v < 0) {
      log_odds_[k] = std::numeric_limits<float>::quiet_NaN();
    } else if (v >= 100) {
      log_odds_[k] = hi;
    } else if (v == 0) {
      log_odds_[k] = lo;
    } else {
      log_odds_[k] = logOddsOf(std::clamp(v / 100.0, free, occupied));
    }
  }
  grid_ = std::make_unique<MatchGrid>(log_odds_.data(), 0, 0, map.width, map.height, map.resolution,
                                      *table_);
  if (coarse == 1) {
    bnb_ = std::make_unique<BranchAndBoundMatcher2D>(*grid_, depth);
    return;
  }
  const std::int64_t cw = (width_ + coarse - 1) / coarse, ch = (height_ + coarse - 1) / coarse;
  coarse_log_odds_.assign(static_cast<std::size_t>(cw * ch),
                          std::numeric_limits<float>::quiet_NaN());
  for (std::int64_t j = 0; j < height_; ++j)
    for (std::int64_t i = 0; i < width_; ++i) {
      const float l = log_odds_[static_cast<std::size_t>(j * width_ + i)];
      float& m = coarse_log_odds_[static_cast<std::size_t>((j / coarse) * cw + i / coarse)];
      if (l == l && !(m >= l)) m = l;  // unknown (NaN) only where every cell is
    }
  coarse_grid_ = std::make_unique<MatchGrid>(coarse_log_odds_.data(), 0, 0, cw, ch,
                                             map.resolution * coarse, *table_);
  bnb_ = std::make_unique<BranchAndBoundMatcher2D>(*coarse_grid_, depth);
}

double MapMatcher2D::crossing(const std::vector<Eigen::Vector2f>& points,
                              const Eigen::Vector2f& sensor, const Pose2D& pose,
                              double clearance) const {
  if (points.empty()) return 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta), inv = 1.0 / resolution_;
  const double ox = pose.x + c * sensor.x() - s * sensor.y();
  const double oy = pose.y + s * sensor.x() + c * sensor.y();
  std::size_t crossed = 0;
  for (const Eigen::Vector2f& p : points) {
    const double ex = pose.x + c * p.x() - s * p.y(), ey = pose.y + s * p.x() + c * p.y();
    const double length = std::hypot(ex - ox, ey - oy);
    const double free_length = length - clearance;
    if (free_length <= 0) continue;
    // Samples every half cell from the sensor to `clearance` before the end.
    const auto steps = static_cast<std::int64_t>(free_length * inv * 2.0);
    const double dx = (ex - ox) / length * resolution_ / 2,
                 dy = (ey - oy) / length * resolution_ / 2;
    for (std::int64_t k = 0; k <= steps; ++k) {
      const auto i = static_cast<std::int64_t>(std::floor((ox + k * dx) * inv));
      const auto j = static_cast<std::int64_t>(std::floor((oy + k * dy) * inv));
      if (i < 0 || j < 0 || i >= width_ || j >= height_) continue;
      if (occupied_[static_cast<std::size_t>(j * width_ + i)]) {
        ++crossed;
        break;
      }
    }
  }
  return static_cast<double>(crossed) / static_cast<double>(points.size());
}

}  // namespace metricmap
