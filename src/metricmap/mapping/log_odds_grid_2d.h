#pragma once
/// \file log_odds_grid_2d.h
/// \brief A 2D probabilistic occupancy grid: beams cast in the plane with OctoMap's sensor model
/// (hits and misses in log-odds, clamped), dense cells that grow with the data.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "metricmap/common/map_server_image.h"
#include "metricmap/occupancy/log_odds_params.h"

namespace metricmap {

/// \brief A cell's state.
enum class CellState { Unknown, Free, Occupied };

/// \brief 2D log-odds occupancy grid. A scan is a sensor position and beam end points in the
/// plane; each scan updates a cell once: the end cells of beams within `max_range` by
/// `prob_hit`, the other cells the beams cross (from the origin's cell, end cells excluded) by
/// `prob_miss`; a cell both crossed and hit in one scan counts as hit. Longer beams are cut at
/// `max_range` and mark only free space. This is OctoMap's insertPointCloud restricted to a
/// plane: the same cells, in float coordinates and double traversal, and the same log-odds.
/// Cell (i, j) spans [i r, (i + 1) r) x [j r, (j + 1) r) for resolution r.
/// \note Thread safety: one instance per thread; const members may be called concurrently.
class LogOddsGrid2D {
 public:
  /// \throws std::invalid_argument naming the first bad parameter (validateLogOddsParams)
  explicit LogOddsGrid2D(const LogOddsParams& params);
  /// \brief A grid holding `cells` (log-odds, NaN unknown; the layout of data()) over
  /// [min_i, min_i + width) x [min_j, min_j + height): one saved before, as it was.
  /// \throws std::invalid_argument for a bad parameter, a negative size or one that is not
  /// width x height, a corner beyond +-2^30 cells, or an infinite cell
  LogOddsGrid2D(const LogOddsParams& params, std::int64_t min_i, std::int64_t min_j,
                std::int64_t width, std::int64_t height, std::vector<float> cells);

  /// \brief Cast the beams from `origin` to each of `ends` (world plane coordinates, m).
  /// Non-finite end points are skipped.
  /// \throws CapacityError when the grid would outgrow the memory budget or the cell range
  /// (+-2^30 cells); the grid is unchanged then
  void insertScan(const Eigen::Vector2f& origin, const std::vector<Eigen::Vector2f>& ends);

  /// \brief Scans inserted so far.
  std::size_t scans() const { return scans_; }
  const LogOddsParams& params() const { return params_; }
  /// \brief Cells observed at least once / occupied / free (occupied: log-odds >= threshold).
  std::size_t knownCells() const;
  std::size_t occupiedCells() const;
  std::size_t freeCells() const { return knownCells() - occupiedCells(); }

  /// \brief State and log-odds of cell (i, j); log-odds 0 for an unknown cell.
  CellState state(std::int64_t i, std::int64_t j) const;
  float logOdds(std::int64_t i, std::int64_t j) const;

  /// \brief The dense storage: cells (i, j) for i in [minI(), minI() + width()) and j in
  /// [minJ(), minJ() + height()), row by row at data()[(j - minJ()) width() + (i - minI())],
  /// log-odds, NaN where unknown. Valid until the next insertScan.
  std::int64_t minI() const { return i0_; }
  std::int64_t minJ() const { return j0_; }
  std::int64_t width() const { return w_; }
  std::int64_t height() const { return h_; }
  const float* data() const { return cells_.data(); }

  /// \brief Calls f(i, j, log_odds) for every known cell, row by row (j, then i, ascending).
  template <typename F>
  void forEachKnown(F&& f) const {
    for (std::int64_t r = 0; r < h_; ++r)
      for (std::int64_t c = 0; c < w_; ++c) {
        const float l = cells_[static_cast<std::size_t>(r * w_ + c)];
        if (l == l) f(i0_ + c, j0_ + r, l);
      }
  }

  /// \brief The known cells' bounds as map_server images (row 0 at the top, origin the lower-
  /// left corner): trinary (occupied 0, free 254, unknown 205; `mode: trinary`) or probability
  /// (255 (1 - p), unknown 205; `mode: scale`).
  /// \throws std::invalid_argument when no cell is known
  MapServerImage trinaryImage() const;
  MapServerImage probabilityImage() const;

  /// \brief Bytes of the grid's storage (cells and per-scan marks).
  std::uint64_t memoryBytes() const {
    return (cells_.capacity() + marks_.capacity()) * 4 +
           (hit_list_.capacity() + free_list_.capacity()) * sizeof(std::size_t);
  }
  /// \brief Bytes held beside this grid by the work it is part of (a SLAM's other submaps):
  /// the grid grows only while its storage, its copy while growing and these fit the budget.
  void setMemoryHeldElsewhere(std::uint64_t bytes) { held_elsewhere_ = bytes; }

 private:
  void growTo(std::int64_t i_lo, std::int64_t j_lo, std::int64_t i_hi, std::int64_t j_hi);
  std::size_t index(std::int64_t i, std::int64_t j) const {
    return static_cast<std::size_t>((j - j0_) * w_ + (i - i0_));
  }
  template <typename Pixel>
  MapServerImage image(MapServerMode mode, Pixel pixel) const;

  LogOddsParams params_;
  double inv_res_;
  float hit_, miss_, clamp_min_, clamp_max_, threshold_;
  std::int64_t i0_ = 0, j0_ = 0, w_ = 0, h_ = 0;  ///< cells cover [i0, i0 + w) x [j0, j0 + h)
  std::vector<float> cells_;                      ///< log-odds; NaN = unknown
  std::vector<std::uint32_t> marks_;              ///< per scan: 2s + 1 hit, 2s + 2 crossed
  std::vector<std::size_t> hit_list_, free_list_;
  std::size_t scans_ = 0;
  std::uint32_t stamp_ = 0;
  std::uint64_t held_elsewhere_ = 0;
};

}  // namespace metricmap
