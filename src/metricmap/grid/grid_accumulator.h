#pragma once
/// \file grid_accumulator.h
/// \brief metricmap::GridAccumulator — the per-cell (key, count, sum) table of a world-aligned
/// grid, built per part of the input, serialised, and merged: the merge of the parts equals the
/// grid of the whole input (counts exactly, means to ~1e-15 relative).

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "metricmap/grid/grid_types.h"

namespace metricmap {

/// \brief One cell of a GridAccumulator: world-aligned index, point count, coordinate sums.
struct CellSum {
  std::array<std::int64_t, 3> index{};
  std::uint64_t count = 0;
  std::array<double, 3> sum{};
};

/// \brief What the statistics of a set of cells need: they reduce with sums and min/max.
struct GridSummary {
  std::uint64_t input_points = 0, skipped_points = 0, points = 0, cells = 0;
  std::array<std::int64_t, 3> min_index{}, max_index{};  ///< of the cells (when cells > 0)
};

/// \brief Layout and statistics (no cells) of a summary.
/// \throws CapacityError when the bounding volume has 2^64 cells or more
GridResult gridStatisticsOf(const GridSummary& summary, float cell_size);

/// \brief Mergeable grid statistics. Keys are world-aligned (GridOrigin::WorldAligned: index =
/// floor(p * (1 / cell)) in float), so parts built independently agree on every cell; the
/// CloudMinimum partition depends on the whole cloud's minimum and cannot be merged this way.
///
/// A part's sums are its cells' mean * count (the kernel keeps means); that product is within
/// an ulp or two of the part's own sum, so merged means match the one-process means to ~1e-15
/// relative (tested to 1e-12). Cells' `first_point` is not kept: merged cells report 0.
/// \note Thread safety: one instance per thread.
class GridAccumulator {
 public:
  /// \throws std::invalid_argument unless the cell size is finite and > 0
  explicit GridAccumulator(float cell_size);

  /// \brief Add one part: a GridOrigin::WorldAligned build at this cell size, and how many
  /// points its input had (finite or not; the `points` figure the CLI prints).
  /// \throws std::invalid_argument when the build is not world-aligned at this cell size
  void add(const GridResult& part, std::uint64_t input_points);

  /// \brief Add another accumulator's cells and totals.
  /// \throws std::invalid_argument when the cell sizes differ
  void merge(const GridAccumulator& other);

  /// \brief Versioned buffer with every cell and the totals (56 bytes per cell + 40).
  std::vector<std::uint8_t> serialize() const;
  /// \brief One buffer per owner (tileOwner of the cell index): buffer k holds the cells part k
  /// owns; the totals travel in buffer 0 only, so they are counted once after the exchange.
  std::vector<std::vector<std::uint8_t>> serializeByOwner(unsigned parts) const;
  /// \brief Read a buffer written by serialize().
  /// \throws InputError (naming `what`) when the buffer is truncated, too long, of another
  /// format or version, or holds an impossible cell (count 0, non-finite sum)
  static GridAccumulator deserialize(const std::uint8_t* data, std::size_t size,
                                     const std::string& what);

  /// \brief The merged grid: cells in linear-index order, layout = bounding box of the
  /// occupied cells (world-aligned, the one-process layout), statistics.
  /// \throws CapacityError when the bounding volume has 2^64 cells or more
  GridResult result() const;

  /// \brief Totals and cell box of the (distinct) cells held.
  GridSummary summary() const;

  float cellSize() const { return cell_size_; }
  std::uint64_t inputPoints() const { return input_points_; }
  /// \brief Distinct cells held (after merging equal keys).
  std::size_t cellCount() const;
  /// \brief Cells, sorted by linear index (z, then y, then x), equal keys merged.
  const std::vector<CellSum>& cells() const;

 private:
  void normalize() const;
  float cell_size_;
  std::uint64_t input_points_ = 0, skipped_points_ = 0;
  mutable std::vector<CellSum> cells_;
  mutable bool sorted_ = true;
};

}  // namespace metricmap
