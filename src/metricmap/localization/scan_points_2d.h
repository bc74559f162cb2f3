#pragma once
/// \file scan_points_2d.h
/// \brief A laser scan as the matcher's points: beams within the range limits, placed on the
/// robot, one point kept per square of the voxel filter's edge.

#include <vector>

#include <Eigen/Core>

#include "metricmap/common/pose_2d.h"
#include "metricmap/io/laser_scan.h"

namespace metricmap {

/// \brief End points of the beams with min_range <= range <= max_range (finite angle), in the
/// robot's frame (`sensor_to_base` applied), then the first point of each square of `voxel`
/// (m), in beam order.
std::vector<Eigen::Vector2f> scanPoints2D(const LaserScan& scan, const Pose2D& sensor_to_base,
                                          double min_range, double max_range, double voxel);

/// \brief At most `count` of `points`, evenly spread over their order.
std::vector<Eigen::Vector2f> spreadSubset(const std::vector<Eigen::Vector2f>& points,
                                          std::size_t count);

}  // namespace metricmap
