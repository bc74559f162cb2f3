#pragma once
/// \file bag_source.h
/// \brief A ROS bag (rosbag2 sqlite3 .db3 or a rosbag2 folder, MCAP .mcap) as a ScanSource:
/// the messages of one topic, sensor_msgs/(msg/)PointCloud2 as 3D scans (io/point_cloud2.h) or
/// sensor_msgs/(msg/)LaserScan as planar 2D scans (beams at z = 0, like the CARMEN source).
///
/// The topic: ScanSourceOptions::topic, or else the bag's only PointCloud2 or LaserScan topic
/// (only PointCloud2 with bag_scans "cloud", only LaserScan with "laser"); several candidates,
/// none, or a named topic of another type or not in the bag throw TopicSelectionError listing
/// the candidates (the CLI exits 2).
///
/// Opening lists the topics, indexes the selected topic (16 bytes per message, in log-time
/// order) and decodes its first message (whether scans carry per-point times); scan(i) reads
/// and decodes message i only. Scan::stamp is the message header's stamp;
/// SourceInfo::stamps are the bag's receive (log) times, known without reading the messages.
/// Reference poses only from ScanSourceOptions::reference_poses (one row per message); identity
/// extrinsic.

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/io/bag_reader.h"

namespace metricmap {

/// \brief The topic to read cannot be chosen from what was given: the message names the bag,
/// the topic (and its type) or the candidates.
class TopicSelectionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// \brief What a topic's type is to a scan source.
enum class BagScanType { None, PointCloud2, LaserScan };
/// \brief PointCloud2 / LaserScan from "sensor_msgs/msg/X" (ROS 2) or "sensor_msgs/X" (ROS 1).
BagScanType bagScanType(const std::string& type);

/// \brief The topic a source opens, following the rules above (`scans`: "any", "cloud",
/// "laser"). \throws TopicSelectionError; std::invalid_argument for another `scans`
const BagTopic& selectBagTopic(const BagReader& bag, const std::string& topic,
                               const std::string& scans = "any");

class BagSource : public ScanSource {
 public:
  /// \throws InputError naming the file; TopicSelectionError
  BagSource(const std::string& path, const ScanSourceOptions& options);
  ~BagSource() override;
  std::size_t size() const override { return index_.size(); }
  Scan scan(std::size_t i) override;
  const SourceInfo& info() const override { return info_; }
  const BagTopic& topic() const { return topic_; }
  const BagReader& bag() const { return *bag_; }

 private:
  std::unique_ptr<BagReader> bag_;
  BagTopic topic_;
  BagScanType type_ = BagScanType::None;
  MessageReader::Encoding encoding_ = MessageReader::Encoding::Cdr;
  std::vector<BagMessageRef> index_;
  std::vector<std::uint8_t> buffer_;
  SourceInfo info_;
};

/// \brief Open a bag as a source (a BagSource). \throws InputError, TopicSelectionError
std::unique_ptr<ScanSource> openBagSource(const std::string& path,
                                          const ScanSourceOptions& options = {});

}  // namespace metricmap
