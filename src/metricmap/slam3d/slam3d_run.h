#pragma once
/// \file slam3d_run.h
/// \brief Slam3D over a scan source: each selected scan through the LiDAR odometry (sensor
/// profile from the first scan, deskew from per-point times, as runOdometry), then into Slam3D;
/// the graph finished and optimised at the end. The maps are built afterwards from the source
/// with the final poses (SequenceMapper), so the run holds the nodes' downsampled scans only.

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "metricmap/common/trajectory.h"
#include "metricmap/sequence/odometry_run.h"
#include "metricmap/slam3d/slam3d.h"

namespace metricmap {

class ScanSource;

/// \brief Settings of a run.
struct Slam3DRunOptions {
  Slam3DConfig slam;
  /// \brief The odometry: its parameters, sensor profile, frames (empty: every scan), deskew.
  OdometryRunOptions odometry;
};

/// \brief Called after each scan: (scans done, scans in all, the SLAM so far). It may throw to
/// cancel the run (the exception propagates).
using Slam3DProgress = std::function<void(std::size_t, std::size_t, const Slam3D&)>;

/// \brief A finished run.
struct Slam3DRun {
  std::unique_ptr<Slam3D> slam;
  /// \brief The optimised poses in the convention of the source's pose files (as runOdometry:
  /// KITTI's camera 0 in the frame of camera 0 of the first frame, otherwise the sensor in the
  /// frame of the first scan), with stamps when every scan has one.
  Trajectory trajectory;
  /// \brief The odometry's poses alone, same convention.
  Trajectory odometry;
  /// \brief Sensor -> map world poses of the nodes for SequenceMapper (the map's world of
  /// mapConvention: KITTI's camera 0 of the first frame, otherwise the first sensor).
  std::vector<Eigen::Isometry3d> map_poses;
  std::vector<std::size_t> frames;      ///< source index of each node
  LidarOdometryConfig odometry_config;  ///< as used (after the sensor profile)
  double read_seconds = 0.0;            ///< reading scans
  double odometry_seconds = 0.0;        ///< registering them
  double slam_seconds = 0.0;  ///< Slam3D (descriptors, search, verification, optimisation)
};

/// \brief Run the odometry and Slam3D over the selected scans of `source`, then finish.
/// \throws InputError naming a scan that cannot be read or registered; std::invalid_argument
/// for bad options
Slam3DRun runSlam3D(ScanSource& source, const Slam3DRunOptions& options,
                    const Slam3DProgress& progress = {});

}  // namespace metricmap
