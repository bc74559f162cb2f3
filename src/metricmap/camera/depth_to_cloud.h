#pragma once
/// \file depth_to_cloud.h
/// \brief Depth image -> organized point cloud (pinhole model), optionally coloured.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/io/depth_image.h"

namespace metricmap {

/// \brief Organized cloud (width x height) in the camera optical frame (x right, y down,
/// z forward): z = d * depth_scale, x = (u - cx) z / fx, y = (v - cy) z / fy; NaN where d = 0.
/// \throws std::invalid_argument for depth_scale <= 0 / NaN or bad intrinsics
pcl::PointCloud<pcl::PointXYZ> depthToCloud(const DepthImage& depth, const CameraIntrinsics& k,
                                            double depth_scale);

/// \brief The same, coloured from a registered RGB image of the same size.
/// \throws std::invalid_argument also when the sizes differ
pcl::PointCloud<pcl::PointXYZRGB> depthToCloud(const DepthImage& depth, const CameraIntrinsics& k,
                                               double depth_scale, const RgbImage& rgb);

}  // namespace metricmap
