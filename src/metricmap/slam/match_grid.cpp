#include "metricmap/slam/match_grid.h"

#include <cmath>

namespace metricmap {

ProbabilityTable::ProbabilityTable(const LogOddsParams& params) : table_(kSamples + 1) {
  lo_ = logOddsOf(params.clamp_min);
  const float hi = logOddsOf(params.clamp_max);
  scale_ = static_cast<float>(kSamples - 1) / (hi - lo_);
  for (int k = 0; k <= kSamples; ++k)
    table_[k] = static_cast<float>(probabilityOf(lo_ + static_cast<float>(k) / scale_));
  p_min_ = table_[0];
  p_max_ = table_[kSamples - 1];
}

MatchGrid::MatchGrid(const LogOddsGrid2D& grid, const ProbabilityTable& table)
    : data_(grid.data()),
      table_(&table),
      i0_(grid.minI()),
      j0_(grid.minJ()),
      w_(grid.width()),
      h_(grid.height()),
      res_(grid.params().resolution),
      inv_res_(1.0 / grid.params().resolution) {}

float MatchGrid::interpolate(double x, double y, double& gx, double& gy) const {
  const double u = x * inv_res_ - 0.5, v = y * inv_res_ - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  const auto i = static_cast<std::int64_t>(fu), j = static_cast<std::int64_t>(fv);
  const double a = u - fu, b = v - fv;
  const double p00 = probability(i, j), p10 = probability(i + 1, j);
  const double p01 = probability(i, j + 1), p11 = probability(i + 1, j + 1);
  const double bottom = p00 + a * (p10 - p00), top = p01 + a * (p11 - p01);
  gx = ((1.0 - b) * (p10 - p00) + b * (p11 - p01)) * inv_res_;
  gy = (top - bottom) * inv_res_;
  return static_cast<float>(bottom + b * (top - bottom));
}

}  // namespace metricmap
