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

MatchGrid::MatchGrid(const float* log_odds, std::int64_t min_i, std::int64_t min_j,
                     std::int64_t width, std::int64_t height, double resolution,
                     const ProbabilityTable& table)
    : data_(log_odds),
      table_(&table),
      i0_(min_i),
      j0_(min_j),
      w_(width),
      h_(height),
      res_(resolution),
      inv_res_(1.0 / resolution) {}

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

namespace {

/// Value and derivative of the Catmull-Rom spline through p0..p3 at t in [0, 1] (between p1, p2).
inline void hermite(double p0, double p1, double p2, double p3, double t, double& f, double& df) {
  const double a = 0.5 * (-p0 + 3.0 * p1 - 3.0 * p2 + p3);
  const double b = 0.5 * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3);
  const double c = 0.5 * (-p0 + p2);
  f = p1 + t * (c + t * (b + t * a));
  df = c + t * (2.0 * b + 3.0 * a * t);
}

}  // namespace

float MatchGrid::interpolateCubic(double x, double y, double& gx, double& gy) const {
  const double u = x * inv_res_ - 0.5, v = y * inv_res_ - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  const auto i = static_cast<std::int64_t>(fu), j = static_cast<std::int64_t>(fv);
  const double a = u - fu, b = v - fv;
  double f[4], df[4];
  for (int r = 0; r < 4; ++r) {
    const std::int64_t jj = j - 1 + r;
    hermite(probability(i - 1, jj), probability(i, jj), probability(i + 1, jj),
            probability(i + 2, jj), a, f[r], df[r]);
  }
  double value, dv, dudx, unused;
  hermite(f[0], f[1], f[2], f[3], b, value, dv);
  hermite(df[0], df[1], df[2], df[3], b, dudx, unused);
  gx = dudx * inv_res_;
  gy = dv * inv_res_;
  return static_cast<float>(value);
}

}  // namespace metricmap
