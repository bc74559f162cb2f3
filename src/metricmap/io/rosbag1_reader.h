#pragma once
/// \file rosbag1_reader.h
/// \brief ROS 1 bags (format 2.0: http://wiki.ros.org/Bags/Format/2.0), read from the
/// specification: records of a header (`name=value` fields) and data, Connection records
/// (topic, type from the connection header), Message Data records, Chunks uncompressed, `bz2`
/// (libbz2) or `lz4` (roslz4 frames, liblz4). The file is scanned record by record, one chunk in
/// memory at a time (its declared size checked against the budget and the decompressed bytes);
/// index records are not needed (a bag whose recording was cut off still reads up to the cut).
/// Payloads are in the ROS 1 serialisation (MessageReader::Encoding::Ros1).

#include <memory>
#include <string>

#include "metricmap/io/bag_reader.h"

namespace metricmap {

/// \throws InputError naming the file (and the byte offset) when it is not a bag 2.0 or damaged
std::unique_ptr<BagReader> openRosbag1(const std::string& path);

}  // namespace metricmap
