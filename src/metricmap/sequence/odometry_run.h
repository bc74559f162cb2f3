#pragma once
/// \file odometry_run.h
/// \brief LiDAR odometry over a scan source: the frames in order through LidarOdometry, with the
/// sensor settings chosen from the first scan when not given, deskew from per-point times, the
/// trajectory in the convention of the source's pose files and a per-frame comparison with the
/// source's reference poses.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/common/trajectory.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/evaluation/relative_error.h"
#include "metricmap/evaluation/step_failures.h"
#include "metricmap/registration/level_frame.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/sequence/sensor_profile.h"

namespace metricmap {

/// \brief How per-point times for deskew are found.
enum class DeskewMode {
  Auto,     ///< the scans' per-point times when the source has them, else no deskew
  Off,      ///< never
  Azimuth,  ///< times from the azimuth of a spinning sensor (KITTI's HDL-64E)
};

/// \brief The world the poses of a run (and the maps built from them) are expressed in.
enum class WorldFrame {
  /// \brief Gravity-aligned: z up (the normal of the first scan's ground plane), x/y level, the
  /// origin and heading of the first scan's sensor. For sources in the sensor convention;
  /// KITTI keeps its camera-0 convention (the camera of a car is level).
  Level,
  FirstScan,  ///< the first scan's sensor frame (or camera 0 of the first frame for KITTI)
};

/// \brief "level" or "first-scan".
const char* worldFrameName(WorldFrame w);
/// \brief The inverse of worldFrameName. \throws std::invalid_argument for another name
WorldFrame parseWorldFrame(const std::string& name);

/// \brief Settings of an odometry run.
struct OdometryRunOptions {
  /// \brief The odometry's parameters; range window and voxel are replaced by the sensor
  /// profile's where `profile` says so.
  LidarOdometryConfig config;
  /// \brief Which of range window / voxel the first scan decides (see sensor_profile.h).
  SensorProfileRequest profile;
  /// \brief Scan indices in acquisition order (strictly increasing); empty: every scan.
  std::vector<std::size_t> frames;
  DeskewMode deskew = DeskewMode::Auto;
  WorldFrame world = WorldFrame::FirstScan;
};

/// \brief One registered frame.
struct OdometryFrame {
  std::size_t index = 0;  ///< the scan's index in the source
  std::string name;
  double stamp = 0.0;  ///< NaN when unknown
  OdometryResult result;
  double ms = 0.0;  ///< registration time (reading excluded)
  /// \brief Motion since the previous frame compared with the reference's (output convention):
  /// translation (m) and rotation (deg) of (ref_{k-1}^-1 ref_k)^-1 (est_{k-1}^-1 est_k).
  std::optional<double> diff_m, diff_deg;
  double step_m = 0.0;  ///< length of the motion since the previous frame (output convention)
};

/// \brief What a run gave.
struct OdometryRun {
  /// \brief The poses in the output convention: for KITTI, camera 0 in the frame of camera 0 of
  /// the first frame (as poses/NN.txt); otherwise the sensor in the frame of the first scan.
  Trajectory trajectory;
  std::vector<OdometryFrame> frames;
  LidarOdometryConfig config;  ///< as used (after the sensor profile)
  SensorProfile profile;       ///< what the first scan gave
  bool deskewed = false;
  std::string convention;  ///< "kitti camera 0" or "sensor"
  /// \brief The world of `trajectory`: Level when it was asked and the source's convention is
  /// the sensor's, else FirstScan.
  WorldFrame world = WorldFrame::FirstScan;
  /// \brief With a level world: the ground plane of the first scan (its normal is up, in the
  /// first scan's sensor frame), and the rotation first-scan frame -> level world.
  std::optional<UpEstimate> up;
  Eigen::Isometry3d level = Eigen::Isometry3d::Identity();
  double read_seconds = 0.0;
  /// \brief The source's reference poses of the frames, in the output convention (empty when
  /// the source has none).
  Trajectory reference;
  /// \brief Per-frame relative pose error against `reference` (evo_rpe, delta 1 frame: what
  /// `metricmap evaluate` prints for the written poses); empty without a reference.
  std::optional<RelativeError> rpe;
  /// \brief The steps of `rpe` off by more than 0.3 m or 3 deg (StepFailureLimits' defaults).
  std::optional<StepFailures> failed_steps;
};

/// \brief Called after each frame (progress).
using OdometryObserver =
    std::function<void(const OdometryFrame&, std::size_t done, std::size_t total)>;

/// \brief Register the selected scans of `source` in order.
/// \throws InputError naming a scan that cannot be read or registered
/// \throws std::invalid_argument for a frame list that is not strictly increasing or out of range
OdometryRun runOdometry(ScanSource& source, const OdometryRunOptions& options,
                        const OdometryObserver& observer = {});

}  // namespace metricmap
