#pragma once
/// \file bag_reader.h
/// \brief One interface over the bag containers (rosbag2 sqlite3, MCAP, ROS 1 bag): topics
/// with their types and counts, the messages of one topic in time order, one message read at a
/// time. Readers never hold more than one message (or one chunk) in memory besides the index
/// of the selected topic (16 bytes per message).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "metricmap/io/cdr.h"

namespace metricmap {

/// \brief A topic as the bag lists it.
struct BagTopic {
  std::string name;
  std::string type;      ///< as written: "sensor_msgs/msg/PointCloud2" (ROS 2),
                         ///< "sensor_msgs/PointCloud2" (ROS 1)
  std::string encoding;  ///< "cdr", "ros1"
  std::uint64_t messages = 0;
  std::int64_t first_ns = 0,
               last_ns = 0;  ///< receive times of the first and last message (0: none)
};

/// \brief Where a message is, for the reader that indexed it.
struct BagMessageRef {
  std::uint64_t position = 0;  ///< reader-specific (row id, chunk offset)
  std::uint64_t offset = 0;    ///< reader-specific (record offset in the chunk)
  std::int64_t time_ns = 0;    ///< receive (log) time
};

class BagReader {
 public:
  virtual ~BagReader() = default;
  /// \brief "rosbag2-sqlite3", "mcap", "rosbag1".
  virtual std::string format() const = 0;
  virtual const std::string& path() const = 0;
  virtual const std::vector<BagTopic>& topics() const = 0;
  /// \brief The messages of `topic`, in log time order (ties: as stored).
  /// \throws InputError naming the file; CapacityError when the index exceeds the budget
  virtual std::vector<BagMessageRef> index(const std::string& topic) = 0;
  /// \brief The payload of one message, replacing `out`'s content.
  /// \throws InputError naming the file
  virtual void read(const BagMessageRef& ref, std::vector<std::uint8_t>& out) = 0;
};

/// \brief True when `path` is (or is a rosbag2 folder holding) a bag this build reads:
/// .db3, .mcap, .bag, or a folder with metadata.yaml. Looks at names and the first bytes only.
bool looksLikeBag(const std::string& path);

/// \brief Open a bag: a .db3 / .mcap / .bag file, or a rosbag2 folder (metadata.yaml beside
/// one .db3 or .mcap file). The format is told by the file's first bytes.
/// \throws InputError naming the path when it is not a bag, is damaged, or is split in parts
std::unique_ptr<BagReader> openBag(const std::string& path);

}  // namespace metricmap
