#pragma once
/// \file sensor_profile.h
/// \brief The odometry's range window and voxel size chosen from the first scan's ranges, so
/// that a hand-carried indoor scanner and a car's LiDAR both work without tuning.
///
/// KISS-ICP ties the voxel to the range (voxel = max_range / 100) with a fixed 100 m range,
/// which fits a car. Here the window follows what the sensor sees (docs/ODOMETRY.md has the
/// reasons and the figures):
/// - max_range = 1.25 x the 99.5th percentile of the first scan's ranges, in [10, 100] m;
/// - voxel = max_range / 75, in [0.1, 1.0] m;
/// - min_range = the 0.5th percentile of the ranges, at most 3 m (the carrier's body, the
///   car's roof);
/// - a voxel below 0.75 m gets a coarse stage at 3 x the voxel (turns of tens of degrees
///   between scans, which a fine map alone does not follow), the fine threshold capped at
///   2 x the voxel and the convergence tolerance at 3e-4 (smaller steps move the pose by less
///   than the map's quantisation and cost a third of the time);
/// - scans at least 0.3 s apart (the median interval of the stamps: keyframes of a drive, about
///   a metre and up to ~15 deg apart) predict the next pose by the last translation alone and
///   register every scan from the three best-supported motion hypotheses too
///   (lidar_odometry_config.h), keeping the
///   best-supported result: the last rotation of a balancing or turning platform says little
///   about the next at that rate.
/// On KITTI's HDL-64E this gives 80 m, 1 m, 3 m, no coarse stage; on the hand-carried scanner of
/// balm_realworld_dev 30 m, 0.4 m, 2 m, a 1.2 m coarse stage.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "metricmap/registration/lidar_odometry_config.h"

namespace metricmap {

/// \brief Which values the profile decides (the rest stay as given).
struct SensorProfileRequest {
  bool max_range = true, min_range = true;
  /// \brief The voxel, and with it the coarse stage and the threshold cap.
  bool voxel_size = true;
  /// \brief The motion model (prediction, hypotheses) from the scans' interval.
  bool motion = true;
};

/// \brief What the first scan showed and what was chosen.
struct SensorProfile {
  bool used = false;  ///< false when every value was given
  double median_range = 0.0, p995_range = 0.0;
  double max_range = 0.0, min_range = 0.0, voxel_size = 0.0;
  double coarse_voxel_size = 0.0, max_threshold = 0.0;
  double convergence = 0.0;    ///< 0: the config's
  double scan_interval = 0.0;  ///< median seconds between scans (0: unknown)
  bool keyframes = false;      ///< scan_interval >= 0.3 s: the keyframe motion model
};

/// \brief The profile of a scan (sensor frame points; non-finite points skipped).
/// \throws std::invalid_argument when the scan has fewer than 100 finite points at a range > 0
SensorProfile profileScan(const std::vector<Eigen::Vector3d>& points);

/// \brief Adds the scans' interval to `profile`: the median of the positive differences of
/// consecutive finite `stamps` (the scans a run registers, in order); unknown with fewer than
/// two.
void profileStamps(SensorProfile& profile, const std::vector<double>& stamps);

/// \brief The sensor profiles a run can be given by name: "auto" (from the first scan) and the
/// presets ("kitti": LidarOdometryConfig's defaults, tuned on KITTI's HDL-64E).
const std::vector<std::string>& sensorProfileNames();

/// \brief `config` with the requested values replaced by the profile's. A chosen min_range at
/// or above max_range becomes 0; a given one is kept.
/// \throws std::invalid_argument when a given min_range is not below max_range
LidarOdometryConfig applyProfile(LidarOdometryConfig config, const SensorProfile& profile,
                                 const SensorProfileRequest& request);

}  // namespace metricmap
