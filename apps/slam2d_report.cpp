#include "slam2d_report.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "metricmap/slam/slam_2d.h"

namespace metricmap::cli {

void emitSlam2DReport(const std::string& input, const Slam2D& slam, const Slam2DTimes& times,
                      const std::string& format, OutputSet& outputs) {
  const Slam2DStats& s = slam.stats();
  const double total = times.total, span = times.log;
  const nlohmann::json j = {
      {"input", input},
      {"scans", s.scans},
      {"nodes", s.nodes},
      {"submaps", s.submaps},
      {"loop_searches", s.loop_searches},
      {"loop_closures",
       {{"found", s.loops_found}, {"rejected", s.loops_rejected}, {"kept", slam.loops().size()}}},
      {"optimizations", s.optimizations},
      {"final_chi2", s.final_chi2},
      {"map",
       {{"occupied_cells", slam.map().occupiedCells()}, {"free_cells", slam.map().freeCells()}}},
      {"seconds",
       {{"read", times.read},
        {"local", s.local_seconds},
        {"insert", s.insert_seconds},
        {"loop_search", s.loop_seconds},
        {"optimize", s.optimize_seconds},
        {"map", s.map_seconds},
        {"write", times.write},
        {"total", total}}},
      {"log_seconds", span},
      {"real_time_factor", total > 0 ? span / total : 0.0}};
  if (format == "json") return emit(j.dump(2) + "\n", outputs);
  char text[1024];
  std::snprintf(
      text, sizeof text,
      "%s: %zu scans, %zu nodes, %zu submaps\n"
      "loop closures: %zu found in %zu searches, %zu rejected as outliers; %zu optimisations, "
      "final chi2 %.6g\n"
      "map: %zu occupied, %zu free cells of %.3g m\n"
      "time: %.2f s (read %.2f, local %.2f, insert %.2f, loop search %.2f, optimise "
      "%.2f, map %.2f, write %.2f) for %.6g s of log: %.3gx real time\n",
      input.c_str(), s.scans, s.nodes, s.submaps, s.loops_found, s.loop_searches, s.loops_rejected,
      s.optimizations, s.final_chi2, slam.map().occupiedCells(), slam.map().freeCells(),
      slam.config().map.resolution, total, times.read, s.local_seconds, s.insert_seconds,
      s.loop_seconds, s.optimize_seconds, s.map_seconds, times.write, span,
      total > 0 ? span / total : 0.0);
  emit(text, outputs);
}

}  // namespace metricmap::cli
