#pragma once
/// \file map_matcher_2d.h
/// \brief A Map2D prepared for scan matching: its cells as probabilities (the slam module's
/// MatchGrid) and the branch-and-bound levels over the whole map. Poses here are in the map's
/// grid frame (origin at the lower-left corner of cell (0, 0), axes along the grid).

#include <cstdint>
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
  /// (scale mode) at v / 100 clamped to [free, occupied]; `depth` branch-and-bound levels over
  /// the map coarsened `coarse` times (each coarse cell the most probable of its coarse x coarse
  /// cells: the search is exact on that grid, and a fine search around its result follows).
  /// \throws std::invalid_argument for an empty map; CapacityError beyond the memory budget
  MapMatcher2D(const Map2D& map, double occupied, double free, int depth, int coarse = 1);

  const MatchGrid& grid() const { return *grid_; }
  /// \brief The share of `points` (robot frame, seen from `sensor` in the robot frame) whose
  /// beam, placed at `pose`, passes through an occupied cell of the map more than `clearance`
  /// (m) before its end: a scan that sees through walls is not where `pose` puts it.
  double crossing(const std::vector<Eigen::Vector2f>& points, const Eigen::Vector2f& sensor,
                  const Pose2D& pose, double clearance) const;
  const BranchAndBoundMatcher2D& branchAndBound() const { return *bnb_; }
  /// \brief The cell of the branch-and-bound's grid (m).
  double searchResolution() const { return resolution_ * coarse_; }
  /// \brief The map's extent in its grid frame (m).
  double sizeX() const { return width_ * resolution_; }
  double sizeY() const { return height_ * resolution_; }
  double resolution() const { return resolution_; }

 private:
  std::vector<float> log_odds_;
  std::vector<std::uint8_t> occupied_;  ///< per cell: 1 where the map says occupied
  std::unique_ptr<ProbabilityTable> table_;
  std::unique_ptr<MatchGrid> grid_;
  std::vector<float> coarse_log_odds_;
  std::unique_ptr<MatchGrid> coarse_grid_;
  std::unique_ptr<BranchAndBoundMatcher2D> bnb_;
  int width_ = 0, height_ = 0, coarse_ = 1;
  double resolution_ = 0.0;
};

}  // namespace metricmap
