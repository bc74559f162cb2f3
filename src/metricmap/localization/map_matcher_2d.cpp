#include "metricmap/localization/map_matcher_2d.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/occupancy/log_odds_params.h"

namespace metricmap {

MapMatcher2D::MapMatcher2D(const Map2D& map, double occupied, double free, int depth)
    : width_(map.width), height_(map.height), resolution_(map.resolution) {
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
  for (std::size_t k = 0; k < map.cells.size(); ++k) {
    const int v = map.cells[k];
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
  bnb_ = std::make_unique<BranchAndBoundMatcher2D>(*grid_, depth);
}

}  // namespace metricmap
