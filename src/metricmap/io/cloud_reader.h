#pragma once
/// \file cloud_reader.h
/// \brief Load .pcd (ascii, binary, binary_compressed), .ply and KITTI .bin into a PCL cloud.

#include <string>

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/io/load_report.h"

namespace metricmap {

/// \brief Load a point cloud, the format chosen by extension (.pcd, .ply, .bin; any case).
///
/// Points with a NaN/Inf coordinate are dropped and counted (the result is then unorganized:
/// height 1). PCD headers are checked against the file size before pcl::io reads them; ascii
/// lines with the wrong number of values are skipped and counted (a warning says how many).
/// \throws InputError (one line naming the file) for a missing, unreadable, malformed or
/// truncated file, or one without x/y/z or without any finite point.
/// \note Thread-safe.
/// \brief The file's fields as pcl::io decoded them (.pcd, .ply, .bin), with x, y, z checked to be
/// single float32 fields and the data as long as the declared points. NaN points are kept.
/// \throws InputError (one line naming the file) as loadCloud
LoadReport loadCloudBlob(const std::string& path, pcl::PCLPointCloud2& blob);

template <typename PointT>
LoadReport loadCloud(const std::string& path, pcl::PointCloud<PointT>& cloud);

}  // namespace metricmap
