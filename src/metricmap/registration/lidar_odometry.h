#pragma once
/// \file lidar_odometry.h
/// \brief LiDAR odometry from the scans alone: robust point-to-point ICP of each scan against a
/// voxel-hashed local map, constant-velocity prediction, adaptive correspondence threshold,
/// double downsampling and optional deskew (the method of KISS-ICP, Vizzo et al., RA-L 2023).

#include <cstddef>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include "metricmap/registration/adaptive_threshold.h"
#include "metricmap/registration/lidar_odometry_config.h"
#include "metricmap/registration/point_to_point_icp.h"
#include "metricmap/registration/voxel_hash_map.h"

namespace metricmap {

/// \brief What registering one scan gave.
struct OdometryResult {
  /// \brief Sensor pose in the frame of the first scan (sensor -> first sensor).
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  /// \brief Where the constant-velocity model put it.
  Eigen::Isometry3d prediction = Eigen::Isometry3d::Identity();
  std::size_t points_in = 0;        ///< points given
  std::size_t points_used = 0;      ///< finite and within [min_range, max_range]
  std::size_t points_source = 0;    ///< after the second downsampling: the ICP's source
  std::size_t correspondences = 0;  ///< source points with a map point within the threshold
  int iterations = 0;               ///< Gauss-Newton steps
  double threshold = 0.0;           ///< correspondence threshold used (m)
  int degenerate_directions = 0;    ///< directions held at the prediction (0: none)
  /// \brief Weakest / strongest direction of the surfaces' constraint (0 for the first scan).
  double eigen_ratio = 0.0;
  bool restarted =
      false;  ///< registered again from zero motion (the prediction found too few pairs)
  /// \brief Where the coarse stage put the scan (the prediction when there is none).
  Eigen::Isometry3d coarse = Eigen::Isometry3d::Identity();
  int coarse_iterations = 0;  ///< Gauss-Newton steps of the coarse stage
  /// \brief Fraction of the downsampled points with a map point within the support distance
  /// at the pose (0 for the first scan).
  double support = 0.0;
  /// \brief Which start won when the hypotheses were tried (motionHypotheses' order: 0 the
  /// prediction, 1 its translation alone, 2 zero motion, 3.. turns); -1: not tried.
  int hypothesis = -1;
};

/// \brief Fewest point pairs (source points with a map point within the threshold) a registered
/// frame's pose may rest on. Fewer (a voxel as large as the range window leaves a handful of
/// points: 8 points and 5 pairs at a 100 m voxel on KITTI) and the frame is refused, naming it,
/// rather than given a pose fitted to a few stray points.
constexpr std::size_t kMinOdometryPairs = 20;

/// \brief Scans in, poses out. Give the scans in acquisition order, each in its sensor frame;
/// the first scan's sensor frame is the world. Not thread-safe; one object per sequence.
class LidarOdometry {
 public:
  /// \throws std::invalid_argument naming a parameter out of its range
  explicit LidarOdometry(const LidarOdometryConfig& config = LidarOdometryConfig());

  /// \brief Register the next scan and return its pose.
  /// \param points the scan, sensor frame; NaN/Inf points are skipped
  /// \param times per-point sweep times in [0, 1] (fractions of the frame period), used by
  /// deskew; empty when the sensor gives none
  /// \param name how errors name this scan (default: "frame N", N counted from 0)
  /// \throws InputError naming the scan when it is empty, has no finite point or none in range,
  /// or (a frame after the first) when its registration found fewer than kMinOdometryPairs pairs
  /// \throws std::invalid_argument when deskew is on and `times` does not match `points`, or a
  /// finite point's time is not finite
  OdometryResult registerFrame(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<double>& times = {}, const std::string& name = {});
  /// \brief The same for a PCL cloud (read in place).
  OdometryResult registerFrame(const pcl::PointCloud<pcl::PointXYZ>& scan,
                               const std::vector<double>& times = {}, const std::string& name = {});

  /// \brief Poses of every scan registered so far (sensor -> first sensor).
  const std::vector<Eigen::Isometry3d>& poses() const { return poses_; }
  /// \brief The local map (world = the first scan's sensor frame).
  const VoxelHashMap& localMap() const { return map_; }
  const LidarOdometryConfig& config() const { return config_; }
  /// \brief Forget every scan: the next one becomes the world again.
  void reset();

 private:
  /// ICP from `initial` with the threshold; registered again from `last` (when given) with a
  /// wide threshold (at most `cap` when > 0) when too few pairs are found; then refined with
  /// the fine threshold when the threshold is wider.
  PointToPointIcpResult alignWithRecovery(const std::vector<Eigen::Vector3d>& source,
                                          const VoxelHashMap& map, const Eigen::Isometry3d& initial,
                                          const Eigen::Isometry3d* last, double threshold,
                                          double cap, double convergence, bool& restarted);
  template <class Scan>
  OdometryResult registerScan(const Scan& points, const std::vector<double>& times,
                              const std::string& name);
  /// The scan's points in range, deskewed, downsampled into frame_, source_ (and the coarse
  /// stage's buffers); returns the number of points in range. \throws InputError naming
  /// `label` when too few points are in range.
  template <class Scan>
  std::size_t prepareFrame(const Scan& points, const std::vector<double>& times, bool deskew,
                           const Eigen::Isometry3d& velocity, const std::string& label);
  /// The pose of the prepared frame (coarse stage, then fine stage, from the constant-velocity
  /// prediction); fills `res`. \throws InputError naming `label` when too few pairs are found.
  void alignFrame(const Eigen::Isometry3d& velocity, std::size_t in_range, const std::string& label,
                  OdometryResult& res);
  /// When the result's support is below config_.min_support, ICP from the best-supported motion
  /// hypotheses; replaces `icp` and `start` with the best-supported result.
  void tryHypotheses(const Eigen::Isometry3d& velocity, PointToPointIcpResult& icp,
                     Eigen::Isometry3d& start, OdometryResult& res);
  /// Adds the prepared frame at `pose` to the local maps.
  void addFrameToMaps(const Eigen::Isometry3d& pose);

  LidarOdometryConfig config_;
  VoxelHashMap map_;
  AdaptiveThreshold threshold_;
  std::vector<Eigen::Isometry3d> poses_;
  // Buffers kept from scan to scan (fresh memory is expensive): the scan after the first
  // downsampling, its points' input indices, the ICP's source, the ICP's neighbourhoods.
  std::vector<Eigen::Vector3d> frame_;
  std::vector<int> first_idx_;
  std::vector<Eigen::Vector3d> source_;
  // The coarse stage (config_.coarse_voxel_size > 0): its map, threshold, source and the
  // frame it adds to its map.
  VoxelHashMap coarse_map_;
  AdaptiveThreshold coarse_threshold_;
  std::vector<Eigen::Vector3d> coarse_source_, coarse_frame_;
  PointToPointIcpWorkspace icp_;
};

/// \brief The scan's points as double vectors (no filtering).
std::vector<Eigen::Vector3d> toPoints3d(const pcl::PointCloud<pcl::PointXYZ>& scan);

}  // namespace metricmap
