// libFuzzer target for the ROS bag readers: byte 0 picks what the rest is:
// 0: a bag file named .mcap (MCAP or ROS 1: openBag goes by the magic), 1: a rosbag2 sqlite3
// file, 2/3: a PointCloud2 message (CDR / ROS 1 serialisation), 4/5: a LaserScan message (CDR /
// ROS 1). Every scan topic of a container is read to the end. Anything must either read or raise
// InputError / CapacityError / TopicSelectionError, never crash, hang or allocate without bound.
#include <cstdint>
#include <string>

#include "fuzz_common.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/datasets/bag_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/bag_reader.h"
#include "metricmap/io/point_cloud2.h"

namespace {

template <class F>
void tolerate(F&& f) {
  try {
    f();
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  } catch (const metricmap::TopicSelectionError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool budget = [] {
    metricmap::setMemoryBudget(256u << 20);
    return true;
  }();
  (void)budget;
  if (size < 1) return 0;
  const std::uint8_t kind = data[0] % 6;
  const std::uint8_t* p = data + 1;
  const std::size_t n = size - 1;
  using E = metricmap::MessageReader::Encoding;
  if (kind <= 1) {
    metricmap::fuzz::TempInput in(p, n, "bag", kind == 0 ? ".mcap" : ".db3");
    tolerate([&] {
      auto bag = metricmap::openBag(in.path());
      for (const metricmap::BagTopic& t : bag->topics()) {
        if (metricmap::bagScanType(t.type) == metricmap::BagScanType::None) continue;
        tolerate([&] {
          metricmap::ScanSourceOptions o;
          o.topic = t.name;
          metricmap::BagSource s(in.path(), o);
          for (std::size_t i = 0; i < s.size(); ++i) (void)s.scan(i);
        });
      }
    });
  } else if (kind <= 3) {
    tolerate([&] { metricmap::decodePointCloud2(p, n, kind == 2 ? E::Cdr : E::Ros1, "fuzz"); });
  } else {
    tolerate([&] { metricmap::decodeLaserScan(p, n, kind == 4 ? E::Cdr : E::Ros1, "fuzz"); });
  }
  return 0;
}
