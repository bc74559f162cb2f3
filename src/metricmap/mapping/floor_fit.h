#pragma once
/// \file floor_fit.h
/// \brief The floor plane of a camera-frame cloud, by RANSAC (PCL sample_consensus), as
/// pcl::SACSegmentation computes it.

#include <cstddef>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>

namespace metricmap {

/// \brief Plane n.p + d = 0 in the camera frame, |n| = 1, oriented so the camera is above it
/// (d > 0 = camera height).
struct FloorPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double d = 0.0;
  std::size_t inliers = 0;
  double cameraHeight() const { return d; }
};

/// \brief RANSAC plane (SACMODEL_PERPENDICULAR_PLANE around the camera's up axis -y, within
/// 70 degrees) over every `stride`-th finite point.
/// \throws std::invalid_argument for stride 0 or a threshold that is not finite and > 0
/// \throws InputError (a std::runtime_error) when no plane with at least 100 inliers is found
FloorPlane fitFloor(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud, double distance_threshold,
                    std::size_t stride = 4);

}  // namespace metricmap
