#pragma once
/// \file odometry_file.h
/// \brief Raw odometry from a file: a CARMEN log's (sourceOdometry) or a trajectory file's.

#include <string>

#include "metricmap/common/trajectory.h"

namespace metricmap {

/// \brief The odometry of `path`: every scan's odometry pose and stamp when it is a CARMEN log,
/// else the poses of a trajectory file (KITTI or TUM form, by its lines; KITTI has no stamps).
/// \throws InputError naming the file (what sourceOdometry and readTrajectoryFile throw)
Trajectory readOdometry(const std::string& path);

}  // namespace metricmap
