#include "map_report.h"

#include <cstdio>

#include "cli_common.h"

namespace metricmap::cli {

std::string mapReport(const std::string& format, const MapImage& image, const MapReportFigures& f,
                      std::chrono::steady_clock::time_point t_start) {
  nlohmann::json j = {{"source", f.source},
                      {"poses", f.poses},
                      {"frames", f.frames},
                      {"map",
                       {{"width", image.width},
                        {"height", image.height},
                        {"resolution", f.map_resolution},
                        {"occupied_cells", f.occupied_cells}}},
                      {"seconds", secondsSince(t_start)}};
  if (!f.grid.is_null()) j["occupancy_2d"] = f.grid;
  if (format == "json") return j.dump(2) + "\n";
  char line[256];
  std::snprintf(line, sizeof line,
                "%zu frames (%s poses): map %d x %d cells of %g m, %zu occupied, %.2f s\n",
                f.frames, f.poses.c_str(), image.width, image.height, f.map_resolution,
                f.occupied_cells, secondsSince(t_start));
  std::string text = line;
  if (!f.grid.is_null()) {
    std::snprintf(
        line, sizeof line, "2D occupancy: %d x %d cells of %g m, %zu occupied, %zu free\n",
        f.grid["width"].get<int>(), f.grid["height"].get<int>(), f.grid_resolution,
        f.grid["occupied_cells"].get<std::size_t>(), f.grid["free_cells"].get<std::size_t>());
    text += line;
  }
  return text;
}

}  // namespace metricmap::cli
