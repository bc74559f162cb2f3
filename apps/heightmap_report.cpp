#include "heightmap_report.h"

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "metricmap/mapping/height_map.h"
#include "table.h"

namespace metricmap::cli {

void emitHeightMapReport(const HeightMap& map, const std::vector<HeightMapFloor>& floors,
                         double seconds, const std::string& format, OutputSet& outputs) {
  nlohmann::json floor_list = nlohmann::json::array();
  for (const HeightMapFloor& f : floors) {
    const FloorPlane& p = f.plane;
    floor_list.push_back({{"frame", f.frame},
                          {"plane", {p.normal.x(), p.normal.y(), p.normal.z(), p.d}},
                          {"camera_height", p.cameraHeight()},
                          {"inliers", p.inliers}});
  }
  const HeightMapStatistics& s = map.statistics();
  nlohmann::json j = {{"frames", s.frames},
                      {"map_size", map.size()},
                      {"resolution", map.params().resolution},
                      {"z_bins", map.params().z_bins},
                      {"bin_counts", s.bin_counts},
                      {"points_outside_map", s.points_outside_map},
                      {"points", s.valid_points},  // finite points binned or outside
                      {"obstacle_cells", map.obstacleCells()},
                      {"explored_cells", map.exploredCells()},
                      {"floor", floor_list.empty() ? nlohmann::json(nullptr) : floor_list.front()},
                      {"seconds", seconds}};
  if (floor_list.size() > 1) j["floors"] = floor_list;
  if (format == "json") return emit(j.dump(2) + "\n", outputs);
  Table t({"frames", "points", "outside_map", "obstacle_cells", "explored_cells", "bin_counts"});
  std::string bins;
  for (auto b : s.bin_counts) bins += (bins.empty() ? "" : " ") + std::to_string(b);
  t.addRow({std::to_string(s.frames), std::to_string(s.valid_points),
            std::to_string(s.points_outside_map), std::to_string(map.obstacleCells()),
            std::to_string(map.exploredCells()), bins});
  emitTable(t, format, outputs);
}

}  // namespace metricmap::cli
