#pragma once
/// \file scan_ground_3d.h
/// \brief The ground plane under a 3D scan: the rotation that makes the sensor frame level and
/// the sensor's height above the ground. A scan's roll and pitch (a platform that pitches as it
/// moves) then no longer change its bird's-eye descriptor.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace metricmap {

struct ScanGround {
  bool found = false;  ///< a plane was found (else: level = identity, height from the low points)
  /// \brief Sensor frame -> levelled frame (same origin, z along the ground's normal, the
  /// smallest rotation that does it).
  Eigen::Matrix3d level = Eigen::Matrix3d::Identity();
  double height = 0.0;  ///< the sensor's height above the ground (m)
  std::size_t inliers = 0;
};

/// \brief The ground of `points` (sensor frame, z roughly up): a RANSAC plane (fixed seed)
/// among the lowest 30 % of the points 2–30 m away horizontally, its normal within
/// `max_tilt_deg` of z, inliers within `threshold` (m), refitted to its inliers by least
/// squares. Without at least 30 inliers, the 10th percentile of z gives the height.
ScanGround estimateScanGround(const std::vector<Eigen::Vector3d>& points, double threshold,
                              double max_tilt_deg);

}  // namespace metricmap
