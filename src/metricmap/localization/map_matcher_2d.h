#pragma once
/// \file map_matcher_2d.h
/// \brief A Map2D prepared for scan matching: its cells as probabilities (the slam module's
/// MatchGrid) and the branch-and-bound levels over the whole map. Poses here are in the map's
/// grid frame (origin at the lower-left corner of cell (0, 0), axes along the grid).

#include <memory>
#include <optional>
#include <vector>

#include "metricmap/common/map_2d.h"
#include "metricmap/slam/branch_and_bound_2d.h"
#include "metricmap/slam/match_grid.h"

namespace metricmap {

/// \brief The matchable map. Const members may be called concurrently.
class MapMatcher2D {
 public:
  /// \brief Occupied cells (100) at `occupied`, free (0) and unknown cells at `free`, others
  /// (scale mode) at v / 100 clamped to [free, occupied]; `depth` branch-and-bound levels.
  /// \throws std::invalid_argument for an empty map; CapacityError beyond the memory budget
  MapMatcher2D(const Map2D& map, double occupied, double free, int depth);

  const MatchGrid& grid() const { return *grid_; }
  const BranchAndBoundMatcher2D& branchAndBound() const { return *bnb_; }
  /// \brief The map's extent in its grid frame (m).
  double sizeX() const { return width_ * resolution_; }
  double sizeY() const { return height_ * resolution_; }
  double resolution() const { return resolution_; }

 private:
  std::vector<float> log_odds_;
  std::unique_ptr<ProbabilityTable> table_;
  std::unique_ptr<MatchGrid> grid_;
  std::unique_ptr<BranchAndBoundMatcher2D> bnb_;
  int width_ = 0, height_ = 0;
  double resolution_ = 0.0;
};

}  // namespace metricmap
