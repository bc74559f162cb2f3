#pragma once
/// \file slam_2d.h
/// \brief 2D laser SLAM with submaps and loop closure, after Hess et al., "Real-time loop
/// closure in 2D LIDAR SLAM" (ICRA 2016, Cartographer):
/// - local: each scan is matched against the older of the two active submaps (correlative
///   search about the odometry's prediction, then Gauss-Newton on the interpolated grid);
/// - a scan that moved far enough since the last one kept (the motion filter) becomes a node:
///   it is inserted into both active submaps (2D log-odds grids, free space by ray casting) and
///   added to the pose graph with an edge from the previous node; a submap that received twice
///   `scans_per_submap` nodes is finished and its branch-and-bound levels are built;
/// - global: one node in `loop_every_n_nodes` is searched against every finished submap near
///   its estimate (exact branch-and-bound in the loop window, Gauss-Newton after); a match
///   scoring at least `loop_min_score` adds a loop edge (robust Huber loss) from the submap's
///   first node; the graph is optimised with Ceres every `optimize_every_n_nodes` nodes when
///   loops were added, and once at the end;
/// - the map is rebuilt at the end from every node at its optimised pose.
///
/// Frames: poses are the robot's (base) in a world frame that starts at the first odometry pose
/// (or the origin when the scans come without odometry). Scans are in the sensor frame,
/// `sensor_to_base` places them on the robot.

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "metricmap/common/pose_2d.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/mapping/log_odds_grid_2d.h"
#include "metricmap/posegraph/pose_graph.h"
#include "metricmap/slam/slam_2d_config.h"

namespace metricmap {

/// \brief A loop-closure match found between a node and a finished submap.
struct LoopClosure2D {
  std::size_t node = 0;    ///< node index (= graph vertex index)
  std::size_t submap = 0;  ///< submap index
  std::size_t anchor = 0;  ///< the submap's first node (the edge's `from`)
  double score = 0.0;      ///< refined nearest-cell score
  std::size_t edge = 0;    ///< the graph edge
};

/// \brief Counts and time per phase (seconds, wall clock).
struct Slam2DStats {
  std::size_t scans = 0, nodes = 0, submaps = 0, finished_submaps = 0;
  std::size_t loop_searches = 0;    ///< node-submap pairs searched
  std::size_t loop_candidates = 0;  ///< branch-and-bound candidates scored
  std::size_t loops_found = 0;      ///< matches that reached loop_min_score
  std::size_t loops_rejected = 0;   ///< of those, removed after an optimisation (chi² too large)
  std::size_t optimizations = 0;
  double local_seconds = 0.0;                         ///< scan filtering and local matching
  double insert_seconds = 0.0;                        ///< submap insertion and finishing
  double loop_seconds = 0.0;                          ///< loop-closure search
  double optimize_seconds = 0.0;                      ///< pose-graph optimisation
  double map_seconds = 0.0;                           ///< the final map
  double final_chi2_initial = 0.0, final_chi2 = 0.0;  ///< of the last optimisation
  int final_iterations = 0;
};

/// \brief The SLAM. Not thread-safe.
class Slam2D {
 public:
  /// \throws std::invalid_argument naming the bad configuration value
  explicit Slam2D(const Slam2DConfig& config, const Pose2D& sensor_to_base = {});
  ~Slam2D();
  Slam2D(const Slam2D&) = delete;
  Slam2D& operator=(const Slam2D&) = delete;

  /// \brief Add the next scan with the robot's raw odometry (base -> odometry world), when known,
  /// and its stamp (s; NaN when unknown: the motion filter's time limit then never applies).
  /// Beams with a NaN range are skipped. \throws std::invalid_argument for a scan without beams
  /// or one that breaks validateLaserScan's rules, an infinite stamp, or non-finite odometry;
  /// \throws CapacityError when the maps outgrow the memory budget
  void addScan(const LaserScan& scan, const std::optional<Pose2D>& odometry,
               double stamp = std::numeric_limits<double>::quiet_NaN());

  /// \brief Optimise the graph once more and build the map. Further addScan calls are refused.
  void finish();

  /// \brief The robot's pose at every scan added (after finish: optimised).
  std::vector<Pose2D> trajectory() const;
  /// \brief The pose graph: one vertex per node.
  const PoseGraph2D& graph() const;
  /// \brief The scan index of every node.
  const std::vector<std::size_t>& nodeScans() const;
  /// \brief The loop closures in the graph (found, and not removed as outliers).
  const std::vector<LoopClosure2D>& loops() const;
  /// \brief Every submap's centre (the mean of its nodes' positions) in the global frame, at
  /// the current estimate of its first node: where a picture draws a loop edge from.
  std::vector<Eigen::Vector2d> submapCentres() const;
  /// \brief The map rebuilt from every node (after finish). \throws std::logic_error before
  const LogOddsGrid2D& map() const;
  /// \brief The map so far: built as finish() builds it, from every node at its current
  /// estimate (before finish: without the final optimisation); after finish, a copy of map().
  /// \throws std::invalid_argument before any scan; CapacityError beyond the memory budget
  LogOddsGrid2D currentMap() const;
  const Slam2DStats& stats() const;
  const Slam2DConfig& config() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace metricmap
