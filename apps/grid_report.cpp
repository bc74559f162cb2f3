#include "grid_report.h"

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "stats_json.h"
#include "table.h"

namespace metricmap::cli {

void emitGridReport(const std::vector<std::string>& files, float cell_size,
                    const std::string& origin, const GridOutcome& g, const std::string& format,
                    OutputSet& outputs) {
  const GridStatistics& s = g.stats;
  if (format == "json") {
    nlohmann::json j = {{"points", g.input_points},
                        {"cell_size", cell_size},
                        {"origin", origin},
                        {"grid", s},
                        {"seconds", {{"load", g.load_s}, {"grid", g.grid_s}}}};
    if (files.size() == 1) {
      j["file"] = files[0];
    } else {
      j["files"] = files;
    }
    return emit(j.dump(2) + "\n", outputs);
  }
  std::string names = files[0];
  for (std::size_t i = 1; i < files.size(); ++i) names += "," + files[i];
  Table t({"file", "cell_size", "origin", "points", "total_cells", "occupied_cells", "empty_cells",
           "mean_points_per_occupied_cell"});
  t.addRow({names, readable(cell_size), origin, std::to_string(s.points),
            std::to_string(s.total_cells), std::to_string(s.occupied_cells),
            std::to_string(s.empty_cells), fixed(s.mean_points_per_occupied_cell, 2)});
  emitTable(t, format, outputs);
}

}  // namespace metricmap::cli
