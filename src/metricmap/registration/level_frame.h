#pragma once
/// \file level_frame.h
/// \brief The up direction of a 3D scan from its ground (or floor) plane, and the rotation that
/// levels a world whose first scan's sensor was tilted: x/y level, z up, the first scan's
/// heading kept. A 2D map sliced from a levelled world cuts a level band, not a slanted plane.

#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

namespace metricmap {

/// \brief The ground plane found in a scan: n.p + d = 0 (sensor frame), n the up direction.
struct UpEstimate {
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  ///< unit, pointing from the ground to the sensor
  double height = 0.0;                            ///< the sensor above the plane (m)
  std::size_t inliers = 0;                        ///< points within the RANSAC distance
};

/// \brief The largest plane below the sensor whose normal lies within `max_tilt_deg` of the
/// sensor's z axis (RANSAC over PCL's perpendicular-plane model, fixed seed), refined by least
/// squares over its inliers.
/// \param distance RANSAC inlier distance (m), > 0
/// \throws std::invalid_argument for a distance or tilt out of range
/// \throws InputError when no such plane holds at least 50 points
UpEstimate estimateUp(const std::vector<Eigen::Vector3d>& points, double distance = 0.1,
                      double max_tilt_deg = 45.0);

/// \brief The smallest rotation taking `up` to +z (a rotation about an axis in the x/y plane).
Eigen::Isometry3d levelRotation(const Eigen::Vector3d& up);

}  // namespace metricmap
