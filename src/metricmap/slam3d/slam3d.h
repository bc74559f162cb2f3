#pragma once
/// \file slam3d.h
/// \brief 3D LiDAR SLAM on top of an odometry: every scan becomes a node of an SE(3) pose graph
/// chained by the odometry's motion; each node's local map (its scan and its neighbours') gives
/// a Scan Context descriptor, and loop candidates come from the descriptor (searched over every
/// yaw, so revisits in the opposite direction are found) and from a radius search around the
/// current estimate. Candidates are verified by ICP with an overlap test (loop_verification.h),
/// verified loops enter the graph with a robust (Huber) loss, and the graph is optimised with
/// Ceres as loops come in and at the end.
///
/// Memory: each node keeps its scan downsampled to `voxel` (12 bytes a point) and its
/// descriptor; maps are rebuilt from the source afterwards (SequenceMapper), never from here.
/// Not thread-safe; one object per sequence.

#include <cstddef>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include "metricmap/posegraph/pose_graph.h"
#include "metricmap/slam3d/loop_verification.h"
#include "metricmap/slam3d/scan_context.h"
#include "metricmap/slam3d/slam3d_config.h"

namespace metricmap {

/// \brief One loop candidate and what its verification found.
struct Slam3DLoop {
  std::size_t from = 0;              ///< the earlier node (the candidate)
  std::size_t to = 0;                ///< the node searched
  std::string method;                ///< "descriptor" or "radius"
  double descriptor_distance = 1.0;  ///< Scan Context distance (1 when not compared)
  LoopVerification check;            ///< check.relation: `to` -> `from` frame
};

/// \brief What one call did.
struct Slam3DFrameReport {
  std::size_t node = 0;        ///< node added (addScan) or the last node (finish)
  std::size_t searched = 0;    ///< nodes searched for loops during this call
  std::size_t candidates = 0;  ///< candidates verified during this call
  std::size_t verified = 0;    ///< of those, accepted
  bool optimized = false;      ///< the graph was optimised during this call
  double seconds_search = 0.0, seconds_verify = 0.0, seconds_optimize = 0.0;
};

/// \brief Time spent per phase since construction (s).
struct Slam3DTiming {
  double descriptors = 0.0;  ///< local maps and descriptors
  double search = 0.0;       ///< candidate search
  double verify = 0.0;       ///< ICP verification
  double optimize = 0.0;     ///< pose graph optimisation
  std::size_t optimizations = 0;
};

class Slam3D {
 public:
  /// \throws std::invalid_argument for a bad configuration (validateSlam3DConfig)
  explicit Slam3D(const Slam3DConfig& config = Slam3DConfig());

  /// \brief Add the next scan (sensor frame) with its odometry pose (sensor -> odometry world).
  /// The first node fixes the map's world: the map frame equals the odometry's there.
  /// \throws std::invalid_argument for a pose that is not finite
  Slam3DFrameReport addScan(const pcl::PointCloud<pcl::PointXYZ>& scan,
                            const Eigen::Isometry3d& odometry_pose);

  /// \brief Search the nodes whose local maps were still open, and optimise the graph when it
  /// has loops. Call once after the last scan; addScan is refused afterwards.
  Slam3DFrameReport finish();

  /// \brief Sensor -> map poses of the nodes, current estimate.
  const std::vector<Eigen::Isometry3d>& poses() const { return poses_; }
  /// \brief The odometry's poses as given.
  const std::vector<Eigen::Isometry3d>& odometryPoses() const { return odometry_; }
  const PoseGraph3D& graph() const { return graph_; }
  /// \brief Every candidate verified, accepted or not, in the order checked.
  const std::vector<Slam3DLoop>& loopChecks() const { return checks_; }
  std::size_t verifiedLoops() const { return verified_; }
  std::size_t size() const { return nodes_.size(); }
  const Slam3DTiming& timing() const { return timing_; }
  const Slam3DConfig& config() const { return config_; }
  /// \brief Bytes held by the nodes' points and descriptors.
  std::size_t bytes() const;

  /// \brief The local map of node `i` in its frame at the current estimate (its scan and
  /// `local_window` neighbours either side, one point per `local_voxel` cell).
  std::vector<Eigen::Vector3f> localMap(std::size_t i) const;

 private:
  struct Node {
    std::vector<Eigen::Vector3f> points;  ///< sensor frame, downsampled
    double travel = 0.0;                  ///< path length from the first node (m)
    ScanContext descriptor;
    bool described = false;
  };
  /// A node that may close a loop with the current one, and the relative pose to start from.
  struct LoopCandidate {
    std::size_t j;
    Eigen::Isometry3d guess;
    const char* method;
    double distance;
  };
  void search(std::size_t c, Slam3DFrameReport& report);
  /// The candidates of node c among nodes [0, eligible): the nearest by position (radius
  /// search), the nearest by descriptor (place recognition).
  std::vector<LoopCandidate> loopCandidates(std::size_t c, std::size_t eligible) const;
  void optimizeGraph(Slam3DFrameReport& report);

  Slam3DConfig config_;
  ScanContextParams sc_params_;
  LoopVerificationParams verify_params_;
  PoseGraph3D graph_;
  std::vector<Node> nodes_;
  std::vector<Eigen::Isometry3d> odometry_, poses_;
  std::vector<Slam3DLoop> checks_;
  std::size_t verified_ = 0;
  std::size_t next_search_ = 0;     ///< next node whose descriptor is due
  std::size_t last_loop_node_ = 0;  ///< node of the last verified loop
  bool any_loop_ = false;
  bool pending_ = false;            ///< loops added since the last optimisation
  std::size_t last_optimized_ = 0;  ///< node count at the last optimisation
  bool finished_ = false;
  Slam3DTiming timing_;
};

}  // namespace metricmap
