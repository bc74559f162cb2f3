#pragma once
/// \file scan_file.h
/// \brief One LiDAR scan from a file (.pcd, .ply, KITTI .bin, .npy) with what drivers store
/// beside x y z: intensity and per-point time.

#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace metricmap {

/// \brief The finite points of a scan file and, point for point, their intensity and time.
struct ScanFile {
  pcl::PointCloud<pcl::PointXYZ> points;
  std::vector<float> intensity;     ///< empty when the file has no intensity field / column
  std::vector<double> point_times;  ///< seconds from the earliest point; empty when no field
  std::string time_field;           ///< the field the times came from (empty: none)
  std::size_t nonfinite_dropped = 0;
};

/// \brief Field names read as per-point time, in order of preference: the names Ouster (`t`),
/// Velodyne (`time`), Hesai/RoboSense (`timestamp`), `time_stamp` and Livox (`offset_time`)
/// drivers write. Float fields are seconds; 32/64-bit integer fields are nanoseconds.
extern const char* const kPointTimeFields[5];

/// \brief Read a scan: points with a NaN/Inf coordinate are dropped with their intensity and
/// time. A time field must be one float32/float64 or 32/64-bit integer value per point, finite,
/// spanning at most 10 s (one sweep); .npy and .bin files carry no time.
/// \throws InputError naming the file (unreadable, no finite point, bad time field)
ScanFile readScanFile(const std::string& path);

}  // namespace metricmap
