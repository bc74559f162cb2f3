// metricmap info FILE...: format, fields, points, NaN count, bounds; for bags (.db3, .mcap,
// rosbag2 folders): topics, types, message counts and time spans.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <sstream>

#include <pcl/common/common.h>
#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/io/bag_reader.h"
#include "table.h"

namespace metricmap::cli {
namespace {

struct InfoOptions {
  std::vector<std::string> files;
  std::string format = "table";
};

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

// Nanoseconds since the epoch as exact seconds ("1673400471.837873222").
std::string seconds(std::int64_t ns) {
  const bool negative = ns < 0;
  const std::uint64_t a =
      negative ? 0 - static_cast<std::uint64_t>(ns) : static_cast<std::uint64_t>(ns);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%s%llu.%09llu", negative ? "-" : "",
                static_cast<unsigned long long>(a / 1000000000ULL),
                static_cast<unsigned long long>(a % 1000000000ULL));
  return buf;
}

void runBagInfo(const InfoOptions& o) {
  nlohmann::json records = nlohmann::json::array();
  Table table({"bag", "format", "topic", "type", "messages", "start_s", "end_s", "duration_s"});
  for (const std::string& f : o.files) {
    const std::unique_ptr<BagReader> bag = openBag(f);
    nlohmann::json topics = nlohmann::json::array();
    for (const BagTopic& t : bag->topics()) {
      const bool any = t.messages > 0;
      const std::string start = any ? seconds(t.first_ns) : "-";
      const std::string end = any ? seconds(t.last_ns) : "-";
      const std::string span = any ? seconds(t.last_ns - t.first_ns) : "-";
      table.addRow(
          {f, bag->format(), t.name, t.type, std::to_string(t.messages), start, end, span});
      nlohmann::json j = {
          {"topic", t.name}, {"type", t.type}, {"encoding", t.encoding}, {"messages", t.messages}};
      if (any) {
        j["start_ns"] = t.first_ns;
        j["end_ns"] = t.last_ns;
        j["duration_s"] = static_cast<double>(t.last_ns - t.first_ns) * 1e-9;
      }
      topics.push_back(j);
    }
    records.push_back({{"file", f}, {"format", bag->format()}, {"topics", topics}});
  }
  if (o.format == "json") {
    emit(records.dump(2) + "\n", "");
  } else {
    emitTable(table, o.format);
  }
}

void runInfo(const InfoOptions& o) {
  std::size_t bags = 0;
  for (const std::string& f : o.files) bags += looksLikeBag(f) ? 1 : 0;
  if (bags > 0 && bags != o.files.size())
    throw UsageError("info: give either bags or point cloud files, not both");
  if (bags > 0) return runBagInfo(o);
  nlohmann::json records = nlohmann::json::array();
  Table table({"file", "format", "fields", "points", "nan_inf", "skipped_lines", "min", "max"});
  for (const std::string& f : o.files) {
    pcl::PointCloud<pcl::PointXYZ> cloud;
    const LoadReport r = loadWithWarnings(f, cloud);
    pcl::PointXYZ lo, hi;
    pcl::getMinMax3D(cloud, lo, hi);
    records.push_back({{"file", f},
                       {"format", r.format},
                       {"fields", r.fields},
                       {"width", r.width},
                       {"height", r.height},
                       {"points_in_file", r.points_in_file},
                       {"points", cloud.size()},
                       {"nan_inf_dropped", r.nonfinite_dropped},
                       {"skipped_lines", r.skipped_lines},
                       {"min", {lo.x, lo.y, lo.z}},
                       {"max", {hi.x, hi.y, hi.z}}});
    std::ostringstream mn, mx;
    mn << fixed(lo.x, 3) << " " << fixed(lo.y, 3) << " " << fixed(lo.z, 3);
    mx << fixed(hi.x, 3) << " " << fixed(hi.y, 3) << " " << fixed(hi.z, 3);
    table.addRow({f, r.format, join(r.fields), std::to_string(r.points_in_file),
                  std::to_string(r.nonfinite_dropped), std::to_string(r.skipped_lines), mn.str(),
                  mx.str()});
  }
  if (o.format == "json") {
    emit(records.dump(2) + "\n", "");
  } else {
    emitTable(table, o.format);
  }
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* sub = app.add_subcommand(
      "info", "Format, fields, points, NaN count and bounds; a bag's topics, types, counts, times");
  sub->add_option("files", o->files,
                  "Point cloud files (.pcd, .ply, .bin, .npy), or ROS bags (.db3, .mcap, rosbag2 "
                  "folders)")
      ->required();
  addFormatOption(*sub, o->format, {"table", "csv", "json"});
  sub->callback([o] { runInfo(*o); });
}

}  // namespace metricmap::cli
