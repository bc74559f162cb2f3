#include "occupancy_report.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "table.h"

namespace metricmap::cli {

std::string occupancyReport(const std::string& format, const LogOddsMap& map,
                            const OccupancyTotals& tot, bool with_map, const TrinaryMap& trinary) {
  const LogOddsMemory mem = map.memory();
  const std::size_t occupied = map.occupiedVoxels();
  const double insert_s = tot.insert_cpu_s >= 0 ? tot.insert_cpu_s : tot.insert_s;
  const double ms_per_scan =
      tot.frames == 0 ? 0.0 : 1000.0 * insert_s / static_cast<double>(tot.frames);
  if (format == "json") {
    nlohmann::json j;
    j["frames"] = tot.frames;
    j["points"] = tot.points;
    j["non_finite"] = tot.non_finite;
    j["beams"] = tot.beams;
    j["beams_cut"] = tot.cut;
    j["resolution"] = map.resolution();
    j["voxels"] = {{"known", map.knownVoxels()},
                   {"occupied", occupied},
                   {"free", map.knownVoxels() - occupied}};
    j["bytes"] = mem.bytes;
    j["bytes_per_known_voxel"] = mem.bytes_per_known_voxel;
    j["seconds"] = {{"load", tot.load_s}, {"insert", tot.insert_s}, {"write", tot.write_s}};
    j["ms_per_scan"] = ms_per_scan;
    if (with_map)
      j["map"] = {{"width", trinary.width},
                  {"height", trinary.height},
                  {"occupied", trinary.occupied},
                  {"free", trinary.free}};
    return j.dump(2) + "\n";
  }
  Table tab(
      {"frames", "beams", "beams_cut", "known", "occupied", "free", "bytes/voxel", "ms/scan"});
  char bpv[32], ms[32];
  std::snprintf(bpv, sizeof bpv, "%.1f", mem.bytes_per_known_voxel);
  std::snprintf(ms, sizeof ms, "%.1f", ms_per_scan);
  tab.addRow({std::to_string(tot.frames), std::to_string(tot.beams), std::to_string(tot.cut),
              std::to_string(map.knownVoxels()), std::to_string(occupied),
              std::to_string(map.knownVoxels() - occupied), bpv, ms});
  return renderTable(tab, "table");
}

}  // namespace metricmap::cli
