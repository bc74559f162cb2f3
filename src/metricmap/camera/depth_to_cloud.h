#pragma once
/// \file depth_to_cloud.h
/// \brief Depth image -> organized point cloud (pinhole model), optionally coloured.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/io/depth_image.h"

namespace metricmap {

/// \brief Metres per raw depth unit: `given` when > 0, else the camera file's scale when it has
/// one, else the convention of the image type: 16-bit TIFF in millimetres (0.001, PCL's
/// grabbers), 16-bit PNG in units of 0.2 mm (0.0002, TUM RGB-D).
double depthScaleFor(const DepthImage& depth, const CameraIntrinsics& k, double given = 0.0);

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
