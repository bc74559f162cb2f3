// metricmap info FILE...: format, fields, points, NaN count, bounds.
#include <memory>
#include <sstream>

#include <pcl/common/common.h>
#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
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

void runInfo(const InfoOptions& o) {
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
  CLI::App* sub = app.add_subcommand("info", "Format, fields, points, NaN count and bounds");
  sub->add_option("files", o->files, "Point cloud files (.pcd, .ply, .bin, .npy)")->required();
  addFormatOption(*sub, o->format, {"table", "csv", "json"});
  sub->callback([o] { runInfo(*o); });
}

}  // namespace metricmap::cli
