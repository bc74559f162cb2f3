#include "metricmap/datasets/bag_source.h"

#include "metricmap/common/memory_budget.h"
#include "metricmap/datasets/reference_file.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/point_cloud2.h"

namespace metricmap {
namespace {

std::string candidates(const BagReader& bag) {
  std::string s;
  for (const BagTopic& t : bag.topics()) {
    if (bagScanType(t.type) == BagScanType::None) continue;
    s += (s.empty() ? "" : ", ") + t.name + " (" + t.type + ")";
  }
  return s.empty() ? std::string("none") : s;
}

std::string allTopics(const BagReader& bag) {
  std::string s;
  for (const BagTopic& t : bag.topics())
    s += (s.empty() ? "" : ", ") + t.name + " (" + t.type + ")";
  return s.empty() ? std::string("no topics") : s;
}

}  // namespace

BagScanType bagScanType(const std::string& type) {
  if (type == "sensor_msgs/msg/PointCloud2" || type == "sensor_msgs/PointCloud2")
    return BagScanType::PointCloud2;
  if (type == "sensor_msgs/msg/LaserScan" || type == "sensor_msgs/LaserScan")
    return BagScanType::LaserScan;
  return BagScanType::None;
}

const BagTopic& selectBagTopic(const BagReader& bag, const std::string& topic,
                               const std::string& scans) {
  if (scans != "any" && scans != "cloud" && scans != "laser")
    throw std::invalid_argument("bag scans must be any, cloud or laser, got '" + scans + "'");
  if (!topic.empty()) {
    for (const BagTopic& t : bag.topics()) {
      if (t.name != topic) continue;
      if (bagScanType(t.type) == BagScanType::None)
        throw TopicSelectionError(bag.path() + ": topic " + t.name + " is of type " + t.type +
                                  ", not sensor_msgs/msg/PointCloud2 or LaserScan (scan topics: " +
                                  candidates(bag) + ")");
      return t;
    }
    throw TopicSelectionError(bag.path() + ": no topic " + topic + " (topics: " + allTopics(bag) +
                              ")");
  }
  auto wanted = [&](const BagTopic& t) {
    const BagScanType k = bagScanType(t.type);
    if (k == BagScanType::None) return false;
    return scans == "any" || (scans == "cloud") == (k == BagScanType::PointCloud2);
  };
  const std::string what = scans == "cloud"   ? "sensor_msgs/msg/PointCloud2"
                           : scans == "laser" ? "sensor_msgs/msg/LaserScan"
                                              : "sensor_msgs/msg/PointCloud2 or LaserScan";
  const BagTopic* found = nullptr;
  std::size_t n = 0;
  for (const BagTopic& t : bag.topics()) {
    if (!wanted(t)) continue;
    found = &t;
    ++n;
  }
  if (n == 1) return *found;
  if (n == 0)
    throw TopicSelectionError(bag.path() + ": no " + what + " topic (topics: " + allTopics(bag) +
                              ")");
  std::string list;
  for (const BagTopic& t : bag.topics())
    if (wanted(t)) list += (list.empty() ? "" : ", ") + t.name + " (" + t.type + ")";
  throw TopicSelectionError(bag.path() + ": " + std::to_string(n) + " " + what +
                            " topics; choose one with --topic: " + list);
}

BagSource::BagSource(const std::string& path, const ScanSourceOptions& options)
    : bag_(openBag(path)) {
  topic_ = selectBagTopic(*bag_, options.topic, options.bag_scans);
  type_ = bagScanType(topic_.type);
  if (topic_.encoding == "ros1") {
    encoding_ = MessageReader::Encoding::Ros1;
  } else if (topic_.encoding != "cdr") {
    throw InputError(bag_->path() + ": topic " + topic_.name + " is serialised as '" +
                     topic_.encoding + "', not cdr or ros1");
  }
  index_ = bag_->index(topic_.name);
  if (index_.empty())
    throw InputError(bag_->path() + ": topic " + topic_.name + " has no messages");
  info_.kind = "bag";
  info_.path = path;
  info_.planar = type_ == BagScanType::LaserScan;
  checkMemory(index_.size(), sizeof(double), bag_->path() + ": stamps of topic " + topic_.name);
  info_.stamps.reserve(index_.size());
  for (const BagMessageRef& r : index_) info_.stamps.push_back(double(r.time_ns) * 1e-9);
  if (!options.reference_poses.empty()) {
    info_.reference = readReferencePoses(options.reference_poses, index_.size());
    if (info_.reference.stamps.empty()) info_.reference.stamps = info_.stamps;
    info_.reference_path = options.reference_poses;
  }
  const Scan first = scan(0);
  info_.point_times = !first.point_times.empty();
}

BagSource::~BagSource() = default;

Scan BagSource::scan(std::size_t i) {
  if (i >= index_.size())
    throw InputError(info_.path + ": no scan " + std::to_string(i) + " on topic " + topic_.name +
                     " (" + std::to_string(index_.size()) + " messages, numbered from 0)");
  bag_->read(index_[i], buffer_);
  Scan s;
  s.index = i;
  s.name = bag_->path() + ": topic " + topic_.name + ", message " + std::to_string(i);
  if (type_ == BagScanType::PointCloud2) {
    CloudMessage m = decodePointCloud2(buffer_.data(), buffer_.size(), encoding_, s.name);
    s.points = std::move(m.cloud.points);
    s.intensity = std::move(m.cloud.intensity);
    s.point_times = std::move(m.cloud.point_times);
    s.stamp = m.stamp;
  } else {
    LaserMessage m = decodeLaserScan(buffer_.data(), buffer_.size(), encoding_, s.name);
    s.points = scanToCloud(m.scan);
    s.laser = std::move(m.scan);
    s.intensity = std::move(m.intensity);
    s.stamp = m.stamp;
  }
  return s;
}

std::unique_ptr<ScanSource> openBagSource(const std::string& path,
                                          const ScanSourceOptions& options) {
  return std::make_unique<BagSource>(path, options);
}

}  // namespace metricmap
