#pragma once
/// \file source_odometry.h
/// \brief The raw odometry a source logs with its scans (a CARMEN log's odom_x odom_y
/// odom_theta) as a trajectory with the scans' stamps: what the SLAM benchmark's relation metric
/// interpolates with.

#include "metricmap/common/trajectory.h"
#include "metricmap/datasets/scan_source.h"

namespace metricmap {

/// \brief Every scan's odometry pose and stamp, in the source's order (stamps may step back).
/// Reads the whole source once.
/// \throws InputError naming the source when a scan has no odometry or no finite stamp
Trajectory sourceOdometry(ScanSource& source);

}  // namespace metricmap
