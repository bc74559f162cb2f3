#pragma once
/// \file lidar_odometry_config.h
/// \brief Parameters of LidarOdometry (KISS-ICP-like scan-to-map odometry), with their defaults.

namespace metricmap {

/// \brief Parameters of LidarOdometry. Distances in metres.
struct LidarOdometryConfig {
  /// \brief Returns farther than this are dropped; also the radius of the local map around the
  /// sensor and the lever arm that turns a rotation error into metres for the threshold.
  double max_range = 100.0;
  /// \brief Returns closer than this are dropped (the vehicle itself).
  double min_range = 3.0;
  /// \brief Cell of the local map. Scans enter the map downsampled at half of it, and register
  /// with a second downsampling at 1.5 times it.
  double voxel_size = 1.0;
  /// \brief Points kept per map cell (1..1000); later points falling in a full cell are
  /// discarded.
  int max_points_per_voxel = 20;
  /// \brief Standard deviation (m) of the prediction error assumed until motion has been seen;
  /// the correspondence threshold is three standard deviations.
  double initial_threshold = 2.0;
  /// \brief Lower bound of the correspondence threshold (m), so that a run of near-perfect
  /// predictions cannot shrink it below what the next abrupt change of speed needs.
  double min_threshold = 0.3;
  /// \brief Smallest prediction error (m) a frame records in the threshold statistics: a
  /// standing vehicle's near-zero errors then narrow the threshold to 3 times this, no further.
  double min_deviation = 0.1;
  /// \brief When the adaptive threshold is wider than this (m), the scan is registered again
  /// from the result with this threshold: a wide threshold (the first frames, after a jolt)
  /// admits the ground rings that travel with the sensor, and they pull towards zero motion.
  /// 0 turns the second pass off.
  double fine_threshold = 1.0;
  /// \brief Gauss-Newton iterations per scan, at most.
  int max_iterations = 500;
  /// \brief Stop when the update's norm (translation m + rotation rad) is below this.
  double convergence = 1e-4;
  /// \brief A direction of the 6-DoF problem whose curvature is below this fraction of the
  /// largest is degenerate (a corridor, a tunnel): the update leaves it at the prediction.
  double degeneracy_ratio = 1e-3;
  /// \brief When fewer than this fraction of the scan's points find a map point near the
  /// constant-velocity prediction, the scan is registered again from the last pose (zero
  /// motion) with the initial threshold, and the better of the two kept.
  double min_inlier_fraction = 0.3;
  /// \brief Correct the motion within a sweep using per-point times and the constant-velocity
  /// model (needs the times).
  bool deskew = false;
  /// \brief Fewest points a frame must have within [min_range, max_range]: a sweep of a
  /// few dozen points (a truncated or filtered file) constrains no pose, so it is refused
  /// naming the frame rather than registered to noise. A real sweep has ~100k.
  int min_points = 100;
  /// \brief Upper bound of the correspondence threshold (m); 0: none. The map is searched in
  /// the 27 voxels around a point, so pairs much farther than a voxel are not found anyway, and
  /// a threshold grown by a sharp turn (its rotation error times the range) only slows the ICP
  /// and widens its robust kernel.
  double max_threshold = 0.0;
  /// \brief Voxel (m) of a second, coarser local map; 0: none. When set, each scan is first
  /// registered on the coarse map from the motion model's prediction (a wide basin: it follows
  /// turns of tens of degrees the prediction misses), then on the fine map from there (the
  /// accuracy of the fine voxel). For sensors that turn faster than a car (hand-carried).
  double coarse_voxel_size = 0.0;
  /// \brief Share of the last motion's rotation the prediction repeats, in [0, 1]: 1 is the
  /// constant-velocity model; 0 repeats only the translation (a platform whose rotation between
  /// scans swings back and forth, as a balancing Segway's between keyframes).
  double prediction_rotation = 1.0;
  /// \brief When the registered scan's support (the fraction of its downsampled points with a
  /// map point within `support_distance`) is below this, the motions a robot allows are tried
  /// as well (zero motion, the prediction's translation without its rotation, turns about each
  /// axis: motion_hypotheses.h) and the best-supported result kept. 0: never (one ICP per scan).
  double min_support = 0.0;
  /// \brief Distance (m) at which supports are compared; 0: the voxel size.
  double support_distance = 0.0;
  /// \brief Angle (deg) between the turned hypotheses (also twice it about z), in (0, 90].
  double hypothesis_step_deg = 5.0;
  /// \brief Hypotheses, besides the prediction, registered by ICP when they are tried: the
  /// best-supported starts (1..16).
  int hypothesis_count = 2;
  /// \brief Threads for the scan-to-map pairing (0: all hardware threads), kept by the object
  /// from scan to scan. The poses do not depend on it: the normal equations are summed in a
  /// fixed order.
  unsigned threads = 0;
};

}  // namespace metricmap
