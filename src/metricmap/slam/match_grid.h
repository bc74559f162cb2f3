#pragma once
/// \file match_grid.h
/// \brief A 2D log-odds grid seen as probabilities, for scan matching: nearest-cell and bilinear
/// (with gradient) look-ups. Unknown cells, and cells outside the grid, count as the lowest
/// probability the grid can hold (Cartographer's convention), so that a scan is not drawn into
/// unexplored space.

#include <cstdint>
#include <vector>

#include "metricmap/mapping/log_odds_grid_2d.h"

namespace metricmap {

/// \brief Log-odds -> probability by table (linear between 4096 samples of the clamped range).
class ProbabilityTable {
 public:
  /// \brief For a grid with these parameters (their clamping bounds).
  explicit ProbabilityTable(const LogOddsParams& params);
  /// \brief Probability of log-odds `l`; `min()` for NaN (unknown).
  float operator()(float l) const {
    if (!(l == l)) return p_min_;
    float u = (l - lo_) * scale_;
    u = u < 0.0f ? 0.0f : (u > kLast ? kLast : u);
    const int k = static_cast<int>(u);
    const float f = u - static_cast<float>(k);
    return table_[k] + f * (table_[k + 1] - table_[k]);
  }
  float min() const { return p_min_; }
  float max() const { return p_max_; }

 private:
  static constexpr int kSamples = 4096;
  static constexpr float kLast = static_cast<float>(kSamples - 1) - 1e-3f;
  std::vector<float> table_;
  float lo_ = 0.0f, scale_ = 1.0f, p_min_ = 0.0f, p_max_ = 1.0f;
};

/// \brief A probability view over a LogOddsGrid2D's storage (no copy): valid until the grid
/// changes. Cell (i, j) has its centre at ((i + 1/2) r, (j + 1/2) r).
class MatchGrid {
 public:
  MatchGrid(const LogOddsGrid2D& grid, const ProbabilityTable& table);
  /// \brief A view over log-odds cells (i, j) for i in [min_i, min_i + width), j in [min_j,
  /// min_j + height), row by row, NaN where unknown (LogOddsGrid2D's layout): valid while they are.
  MatchGrid(const float* log_odds, std::int64_t min_i, std::int64_t min_j, std::int64_t width,
            std::int64_t height, double resolution, const ProbabilityTable& table);

  double resolution() const { return res_; }
  /// \brief Probability of cell (i, j); the table's minimum when unknown or outside.
  float probability(std::int64_t i, std::int64_t j) const {
    const std::int64_t c = i - i0_, r = j - j0_;
    if (c < 0 || r < 0 || c >= w_ || r >= h_) return table_->min();
    return (*table_)(data_[r * w_ + c]);
  }
  /// \brief Bilinear interpolation of the cells' probabilities at world (x, y), and its
  /// gradient (per metre).
  float interpolate(double x, double y, double& gx, double& gy) const;
  /// \brief Bicubic interpolation (Catmull-Rom: the cubic Hermite spline of Ceres'
  /// BiCubicInterpolator, which Cartographer's matcher uses) at world (x, y), and its gradient
  /// (per metre). Its gradient is continuous across cell borders, so a Gauss-Newton step is not
  /// pulled to cell centres as it is on the bilinear surface.
  float interpolateCubic(double x, double y, double& gx, double& gy) const;

  std::int64_t minI() const { return i0_; }
  std::int64_t minJ() const { return j0_; }
  std::int64_t width() const { return w_; }
  std::int64_t height() const { return h_; }
  const ProbabilityTable& table() const { return *table_; }

 private:
  const float* data_;
  const ProbabilityTable* table_;
  std::int64_t i0_, j0_, w_, h_;
  double res_, inv_res_;
};

}  // namespace metricmap
