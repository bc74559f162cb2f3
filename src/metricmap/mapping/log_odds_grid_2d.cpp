#include "metricmap/mapping/log_odds_grid_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/detail/fast_floor.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

constexpr std::int64_t kCellLimit = std::int64_t{1} << 30;
constexpr double kFar = std::numeric_limits<double>::max();  // OctoMap's "no crossing"
/// Below this on both axes (m) an end's float offset from the origin squares to less than the
/// smallest normal float: the walk could not find its direction.
constexpr float kAtOrigin = 1e-18f;
constexpr float kUnknown = std::numeric_limits<float>::quiet_NaN();

/// OctoMap's coordToKey in the plane: floor(coordinate * (1 / resolution)) in double.
bool cellOf(float x, float y, double inv_res, std::int64_t& i, std::int64_t& j) {
  const double u = inv_res * static_cast<double>(x), v = inv_res * static_cast<double>(y);
  const double lim = static_cast<double>(kCellLimit);
  if (!(u >= -lim && u < lim && v >= -lim && v < lim)) return false;
  i = floorToInt(u);
  j = floorToInt(v);
  return true;
}

/// One beam: OctoMap's computeRayKeys state with the third axis never crossed.
struct Beam2 {
  std::int64_t ki, kj, ei, ej, si = 0, sj = 0;
  double ti = kFar, tj = kFar, di = kFar, dj = kFar, length = 0.0;
};

Beam2 startBeam(float ox, float oy, float ex, float ey, std::int64_t ki, std::int64_t kj,
                std::int64_t ei, std::int64_t ej, double res) {
  Beam2 b{ki, kj, ei, ej};
  float dir[2] = {ex - ox, ey - oy};
  const float length = static_cast<float>(
      std::sqrt(static_cast<double>(dir[0] * dir[0] + dir[1] * dir[1] + 0.0f * 0.0f)));
  dir[0] /= length;
  dir[1] /= length;
  const std::int64_t key[2] = {ki, kj};
  const float o[2] = {ox, oy};
  std::int64_t step[2];
  double t[2], d[2];
  for (int a = 0; a < 2; ++a) {
    step[a] = dir[a] > 0.0f ? 1 : (dir[a] < 0.0f ? -1 : 0);
    t[a] = d[a] = kFar;
    if (step[a] != 0) {
      double border = (static_cast<double>(key[a]) + 0.5) * res;
      border += static_cast<float>(static_cast<double>(step[a]) * res * 0.5);
      t[a] = (border - static_cast<double>(o[a])) / static_cast<double>(dir[a]);
      d[a] = res / static_cast<double>(std::fabs(dir[a]));
    }
  }
  b.si = step[0];
  b.sj = step[1];
  b.ti = t[0];
  b.tj = t[1];
  b.di = d[0];
  b.dj = d[1];
  b.length = static_cast<double>(length);
  return b;
}

float updated(float l, float delta, float lo, float hi) {
  if (l != l) l = 0.0f;  // a new cell starts at the prior
  l += delta;
  return l < lo ? lo : (l > hi ? hi : l);
}

}  // namespace

LogOddsGrid2D::LogOddsGrid2D(const LogOddsParams& params) : params_(params) {
  validateLogOddsParams(params_);
  inv_res_ = 1.0 / params_.resolution;
  hit_ = logOddsOf(params_.prob_hit);
  miss_ = logOddsOf(params_.prob_miss);
  clamp_min_ = logOddsOf(params_.clamp_min);
  clamp_max_ = logOddsOf(params_.clamp_max);
  threshold_ = logOddsOf(params_.occupancy_threshold);
}

LogOddsGrid2D::LogOddsGrid2D(const LogOddsParams& params, std::int64_t min_i, std::int64_t min_j,
                             std::int64_t width, std::int64_t height, std::vector<float> cells)
    : LogOddsGrid2D(params) {
  constexpr std::int64_t kReach = std::int64_t{1} << 30;
  if (width < 0 || height < 0 || (width == 0) != (height == 0) ||
      (width > 0 &&
       static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) != cells.size()) ||
      (width == 0 && !cells.empty()))
    throw std::invalid_argument("a saved 2D grid: " + std::to_string(cells.size()) + " cells for " +
                                std::to_string(width) + " x " + std::to_string(height));
  if (std::abs(min_i) > kReach || std::abs(min_j) > kReach || width > kReach || height > kReach)
    throw std::invalid_argument("a saved 2D grid: corner or size beyond 2^30 cells");
  for (float l : cells)
    if (std::isinf(l)) throw std::invalid_argument("a saved 2D grid: an infinite cell");
  checkMemory(cells.size(), sizeof(float) + sizeof(std::uint32_t), "a saved 2D occupancy grid");
  i0_ = width > 0 ? min_i : 0;
  j0_ = width > 0 ? min_j : 0;
  w_ = width;
  h_ = height;
  cells_ = std::move(cells);
  marks_.assign(cells_.size(), 0);
}

void LogOddsGrid2D::growTo(std::int64_t i_lo, std::int64_t j_lo, std::int64_t i_hi,
                           std::int64_t j_hi) {
  if (w_ > 0 && i_lo >= i0_ && j_lo >= j0_ && i_hi < i0_ + w_ && j_hi < j0_ + h_) return;
  if (w_ > 0) {  // grow with slack, so that a moving sensor does not copy the grid each scan
    const std::int64_t mi = std::max<std::int64_t>(64, w_ / 4),
                       mj = std::max<std::int64_t>(64, h_ / 4);
    i_lo = std::min(i0_, i_lo < i0_ ? i_lo - mi : i_lo);
    j_lo = std::min(j0_, j_lo < j0_ ? j_lo - mj : j_lo);
    i_hi = std::max(i0_ + w_ - 1, i_hi >= i0_ + w_ ? i_hi + mi : i_hi);
    j_hi = std::max(j0_ + h_ - 1, j_hi >= j0_ + h_ ? j_hi + mj : j_hi);
  }
  const std::int64_t w = i_hi - i_lo + 1, h = j_hi - j_lo + 1;
  std::ostringstream what;
  what << "the 2D occupancy grid: " << w << " x " << h << " cells of " << params_.resolution
       << " m";
  // the old storage lives until the copy is made
  checkMemoryBeside(static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h),
                    sizeof(float) + sizeof(std::uint32_t), held_elsewhere_ + memoryBytes(),
                    what.str());
  std::vector<float> cells(static_cast<std::size_t>(w * h), kUnknown);
  std::vector<std::uint32_t> marks(cells.size(), 0);
  for (std::int64_t r = 0; r < h_; ++r) {
    const std::size_t from = static_cast<std::size_t>(r * w_);
    const std::size_t to = static_cast<std::size_t>((j0_ + r - j_lo) * w + (i0_ - i_lo));
    std::copy_n(cells_.begin() + from, w_, cells.begin() + to);
    std::copy_n(marks_.begin() + from, w_, marks.begin() + to);
  }
  cells_.swap(cells);
  marks_.swap(marks);
  i0_ = i_lo;
  j0_ = j_lo;
  w_ = w;
  h_ = h;
}

void LogOddsGrid2D::insertScan(const Eigen::Vector2f& origin,
                               const std::vector<Eigen::Vector2f>& ends) {
  const float ox = origin.x(), oy = origin.y();
  std::int64_t oi, oj;
  if (!std::isfinite(ox) || !std::isfinite(oy) || !cellOf(ox, oy, inv_res_, oi, oj)) {
    std::ostringstream msg;
    msg << "sensor position (" << ox << ", " << oy << ") is not finite or outside the 2D grid's "
        << "cell range at " << params_.resolution << " m";
    throw CapacityError(msg.str());
  }
  // Each beam's end (cut at max_range, as OctoMap cuts it) and whether it marks a hit.
  struct End {
    float x, y;
    std::int64_t i, j;
    bool hit;
  };
  std::vector<End> beams;
  beams.reserve(ends.size());
  std::int64_t lo_i = oi, lo_j = oj, hi_i = oi, hi_j = oj;
  const bool cut = std::isfinite(params_.max_range);
  for (const Eigen::Vector2f& e : ends) {
    if (!std::isfinite(e.x()) || !std::isfinite(e.y())) continue;
    const float dx = e.x() - ox, dy = e.y() - oy;
    const double norm = std::sqrt(static_cast<double>(dx * dx + dy * dy + 0.0f * 0.0f));
    End b{e.x(), e.y(), 0, 0, true};
    // An end within 1e-18 m of the origin is the origin: the walk's float direction would
    // underflow (squared length 0) and never reach the neighbouring cell it may lie in.
    if (std::fabs(dx) < kAtOrigin && std::fabs(dy) < kAtOrigin) b = {ox, oy, 0, 0, true};
    if (cut && !(norm <= params_.max_range)) {
      const float fn = static_cast<float>(norm), r = static_cast<float>(params_.max_range);
      b = {ox + dx / fn * r, oy + dy / fn * r, 0, 0, false};
    }
    if (!cellOf(b.x, b.y, inv_res_, b.i, b.j)) {
      std::ostringstream msg;
      msg << "beam end (" << b.x << ", " << b.y << ") is outside the 2D grid's cell range ("
          << "+-2^30 cells of " << params_.resolution << " m)";
      throw CapacityError(msg.str());
    }
    lo_i = std::min(lo_i, b.i);
    lo_j = std::min(lo_j, b.j);
    hi_i = std::max(hi_i, b.i);
    hi_j = std::max(hi_j, b.j);
    beams.push_back(b);
  }
  // Rounding may carry a walk a cell past its end's box before it stops: two cells of margin.
  growTo(lo_i - 2, lo_j - 2, hi_i + 2, hi_j + 2);
  if (stamp_ >= std::numeric_limits<std::uint32_t>::max() / 2 - 1) {
    std::fill(marks_.begin(), marks_.end(), 0);
    stamp_ = 0;
  }
  ++stamp_;
  const std::uint32_t hit_mark = 2 * stamp_ + 1, free_mark = 2 * stamp_ + 2;
  hit_list_.clear();
  free_list_.clear();
  for (const End& b : beams) {
    if (!b.hit) continue;
    const std::size_t k = index(b.i, b.j);
    if (marks_[k] != hit_mark) {
      marks_[k] = hit_mark;
      hit_list_.push_back(k);
    }
  }
  auto crossed = [&](std::int64_t i, std::int64_t j) {
    if (i < i0_ || j < j0_ || i >= i0_ + w_ || j >= j0_ + h_) return;
    const std::size_t k = index(i, j);
    if (marks_[k] == hit_mark || marks_[k] == free_mark) return;
    marks_[k] = free_mark;
    free_list_.push_back(k);
  };
  for (const End& e : beams) {
    if (e.i == oi && e.j == oj) continue;  // OctoMap: one cell, no free space
    Beam2 b = startBeam(ox, oy, e.x, e.y, oi, oj, e.i, e.j, params_.resolution);
    crossed(oi, oj);
    for (;;) {
      // OctoMap's choice, ties included, the third axis at "no crossing"
      const bool i_lt_j = b.ti < b.tj;
      const bool mi = i_lt_j && b.ti < kFar, mj = !i_lt_j && b.tj < kFar;
      if (!mi && !mj) break;
      if (mi) {
        b.ti += b.di;
        b.ki += b.si;
      } else {
        b.tj += b.dj;
        b.kj += b.sj;
      }
      if (b.ki == b.ei && b.kj == b.ej) break;
      const double m = b.ti < b.tj ? b.ti : b.tj;
      if ((m < kFar ? m : kFar) > b.length) break;
      crossed(b.ki, b.kj);
    }
  }
  for (std::size_t k : free_list_) cells_[k] = updated(cells_[k], miss_, clamp_min_, clamp_max_);
  for (std::size_t k : hit_list_) cells_[k] = updated(cells_[k], hit_, clamp_min_, clamp_max_);
  ++scans_;
}

std::size_t LogOddsGrid2D::knownCells() const {
  return static_cast<std::size_t>(
      std::count_if(cells_.begin(), cells_.end(), [](float l) { return l == l; }));
}

std::size_t LogOddsGrid2D::occupiedCells() const {
  const float t = threshold_;
  return static_cast<std::size_t>(
      std::count_if(cells_.begin(), cells_.end(), [t](float l) { return l >= t; }));
}

float LogOddsGrid2D::logOdds(std::int64_t i, std::int64_t j) const {
  if (i < i0_ || j < j0_ || i >= i0_ + w_ || j >= j0_ + h_) return 0.0f;
  const float l = cells_[index(i, j)];
  return l == l ? l : 0.0f;
}

CellState LogOddsGrid2D::state(std::int64_t i, std::int64_t j) const {
  if (i < i0_ || j < j0_ || i >= i0_ + w_ || j >= j0_ + h_) return CellState::Unknown;
  const float l = cells_[index(i, j)];
  if (l != l) return CellState::Unknown;
  return l >= threshold_ ? CellState::Occupied : CellState::Free;
}

template <typename Pixel>
MapServerImage LogOddsGrid2D::image(MapServerMode mode, Pixel pixel) const {
  std::int64_t a0 = std::numeric_limits<std::int64_t>::max(), b0 = a0;
  std::int64_t a1 = std::numeric_limits<std::int64_t>::min(), b1 = a1;
  forEachKnown([&](std::int64_t i, std::int64_t j, float) {
    a0 = std::min(a0, i);
    a1 = std::max(a1, i);
    b0 = std::min(b0, j);
    b1 = std::max(b1, j);
  });
  if (a1 < a0) throw std::invalid_argument("the 2D occupancy grid is empty: no beam was cast");
  MapServerImage out;
  out.width = static_cast<int>(a1 - a0 + 1);
  out.height = static_cast<int>(b1 - b0 + 1);
  out.resolution = params_.resolution;
  out.origin_x = static_cast<double>(a0) * params_.resolution;
  out.origin_y = static_cast<double>(b0) * params_.resolution;
  out.mode = mode;
  out.pixels.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height));
  for (int r = 0; r < out.height; ++r)
    for (int c = 0; c < out.width; ++c)
      out.pixels[static_cast<std::size_t>(r) * out.width + c] =
          pixel(cells_[index(a0 + c, b1 - r)]);
  return out;
}

MapServerImage LogOddsGrid2D::trinaryImage() const {
  const float t = threshold_;
  return image(MapServerMode::Trinary, [t](float l) -> std::uint8_t {
    return l != l ? kMapUnknown : (l >= t ? kMapOccupied : kMapFree);
  });
}

MapServerImage LogOddsGrid2D::probabilityImage() const {
  return image(MapServerMode::Scale, [](float l) -> std::uint8_t {
    if (l != l) return 127;  // the prior, p = 0.5
    return static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - probabilityOf(l))));
  });
}

}  // namespace metricmap
