#pragma once
/// \file point_cloud2.h
/// \brief sensor_msgs/PointCloud2 and sensor_msgs/LaserScan payloads (ROS 2 CDR or ROS 1) as
/// scans. Every size in the message is checked against the bytes it came in.
///
/// PointCloud2: any field layout (offsets, the eight datatypes, either byte order,
/// point_step/row_step with padding, organised or not). x, y, z are required (any numeric
/// type); intensity is kept; the first of the per-point time fields (kPointTimeFields: `t`,
/// `time`, `timestamp`, `time_stamp`, `offset_time`; float: seconds, integer: nanoseconds) gives
/// the times, made relative to the earliest point as readScanFile does. Points with a NaN/Inf
/// coordinate are dropped with their intensity and time (organised clouds too), as the folder
/// source drops them.
///
/// Refused (InputError naming `what`): a field of unknown datatype, count 0, overlapping
/// another or reaching beyond point_step; row_step < width * point_step; a data length other
/// than row_step * height; width * height beyond the memory budget; a time field spanning
/// more than 10 s.

#include <cstddef>
#include <cstdint>
#include <string>

#include "metricmap/io/cdr.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/scan_file.h"

namespace metricmap {

/// \brief A decoded PointCloud2: the points as readScanFile gives them, and the header stamp.
struct CloudMessage {
  ScanFile cloud;
  double stamp = 0.0;  ///< header stamp (s)
  std::uint32_t width = 0, height = 0;
};

/// \brief A decoded LaserScan: beams (angle_min + k * angle_increment; ranges outside
/// [range_min, range_max], non-positive, non-finite or beyond kMaxLaserRange are NaN) and
/// the header stamp.
struct LaserMessage {
  LaserScan scan;
  std::vector<float> intensity;  ///< per beam, empty when the message has none
  double stamp = 0.0;
};

/// \throws InputError "<what>: ..." for a malformed or inconsistent message
CloudMessage decodePointCloud2(const std::uint8_t* data, std::size_t size,
                               MessageReader::Encoding encoding, const std::string& what);
/// \throws InputError "<what>: ..." for a malformed or inconsistent message
LaserMessage decodeLaserScan(const std::uint8_t* data, std::size_t size,
                             MessageReader::Encoding encoding, const std::string& what);

}  // namespace metricmap
