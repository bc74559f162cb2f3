#pragma once
/// \file kitti_bin.h
/// \brief KITTI Velodyne scans: float32 x y z intensity, little-endian, 16 bytes per point.

#include <string>

#include <pcl/PCLPointCloud2.h>

namespace metricmap {

/// \brief Read a KITTI .bin into a blob with fields x, y, z, intensity.
/// \throws InputError naming the file when missing or its size is not a multiple of 16
void readKittiBin(const std::string& path, pcl::PCLPointCloud2& blob);

}  // namespace metricmap
