#pragma once
/// \file branch_and_bound_2d.h
/// \brief Exact multi-resolution correlative matching of a scan against a finished submap
/// (Olson, "Real-time correlative scan matching", ICRA 2009; the branch-and-bound of Hess et
/// al., "Real-time loop closure in 2D LIDAR SLAM", ICRA 2016): level d holds, for every cell,
/// the largest probability over the 2^d x 2^d cells above and to the right of it, so that a
/// candidate's score at level d bounds the score of every pose it covers; the search finds the
/// pose of best nearest-cell score in the window exactly, visiting few candidates.

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "metricmap/slam/match_grid.h"
#include "metricmap/slam/scan_matcher_2d.h"

namespace metricmap {

/// \brief Poses a search must not return: those within `distance` (m) of `centre` and within
/// `angle` (rad) of its heading. The bounds stay exact (excluding poses only lowers maxima), so
/// the search returns the best pose outside the region: the runner-up of a global search.
struct SearchExclusion2D {
  Pose2D centre;
  double distance = 0.0;
  double angle = 0.0;
};

/// \brief The precomputed levels of one submap, and the search over them.
/// Probabilities are held as bytes (round(255 p)): scores are exact in those units.
class BranchAndBoundMatcher2D {
 public:
  /// \brief Levels 0..depth-1 of `grid` (1 <= depth <= 16).
  /// \throws CapacityError when they do not fit in the memory budget beside `held` bytes
  /// already in use (the SLAM's maps)
  BranchAndBoundMatcher2D(const MatchGrid& grid, int depth, std::uint64_t held = 0);

  /// \brief The best pose initial + (dx, dy, dθ), |dx|, |dy| <= linear_window (whole cells),
  /// |dθ| <= angular_window in steps of angularSearchStep, if its score (mean probability in
  /// byte units / 255) reaches min_score; the search prunes every branch whose bound is below the
  /// best found so far. Poses in `exclude`, when given, are never returned.
  std::optional<ScanMatch2D> match(const std::vector<Eigen::Vector2f>& points,
                                   const Pose2D& initial, double linear_window,
                                   double angular_window, double min_score,
                                   const SearchExclusion2D* exclude = nullptr) const;

  /// \brief Candidates whose score was computed in the last match (for the report).
  std::size_t lastCandidates() const { return candidates_; }
  std::size_t bytes() const;

 private:
  struct Level {
    int pad = 0;  ///< 2^d - 1: the level covers base cells [-pad, w) x [-pad, h)
    std::int64_t w = 0, h = 0;
    std::vector<std::uint8_t> cells;
    std::uint8_t at(std::int64_t i, std::int64_t j, std::uint8_t outside) const {
      i += pad;
      j += pad;
      if (i < 0 || j < 0 || i >= w || j >= h) return outside;
      return cells[static_cast<std::size_t>(j * w + i)];
    }
  };
  struct Candidate {
    int angle = 0, dx = 0, dy = 0;
    long score = 0;
  };
  /// The scan's cells at one rotation: per point (i, j) relative to the grid's first cell,
  /// their bounding box, and per level the points' offsets j * w + i in that level's rows.
  struct Rotated {
    std::vector<std::int64_t> i, j;
    std::int64_t i_lo = 0, i_hi = 0, j_lo = 0, j_hi = 0;
    std::vector<std::vector<std::int64_t>> offsets;  ///< [level][point]
  };
  /// What a leaf's pose is, to test it against an exclusion.
  struct Leaves {
    Pose2D initial;
    double step = 0.0;
    int m = 0;
    const SearchExclusion2D* exclude = nullptr;
    bool excluded(const Candidate& c, double res) const;
  };
  long score(std::size_t level, const Rotated& r, int dx, int dy) const;
  void search(const std::vector<Rotated>& rotated, Candidate* todo, std::size_t count, int depth,
              int window, const Leaves& leaves, Candidate& best) const;

  std::vector<Level> levels_;
  std::int64_t i0_ = 0, j0_ = 0;
  double res_ = 0.0;
  std::uint8_t outside_ = 0;
  mutable std::size_t candidates_ = 0;
};

}  // namespace metricmap
