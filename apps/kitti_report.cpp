#include "kitti_report.h"

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "metricmap/mapping/occupancy_map_2d.h"
#include "table.h"

namespace metricmap::cli {
namespace {

nlohmann::json errorJson(const PoseError& e) {
  return {{"translation", e.translation}, {"rotation_deg", e.rotation_deg}};
}

nlohmann::json registrationJson(const KittiOptions& o, const KittiMappingOptions& m,
                                const KittiMappingRun& run) {
  const TrajectoryError err = run.mapper->trajectoryError(run.truths);
  const std::vector<FrameReport>& reports = run.reports;
  nlohmann::json entries = nlohmann::json::array();
  for (std::size_t k = 0; k < reports.size(); ++k) {
    nlohmann::json entry = {{"frame", m.frames[k]}, {"error_before", errorJson(err.given[k])}};
    if (reports[k].registered) {
      entry["correction"] = errorJson(poseError(reports[k].pose_given, reports[k].pose_used));
      entry["converged"] = reports[k].converged;
      entry["fitness"] = reports[k].fitness;
    }
    entry["error_after"] = errorJson(err.used[k]);
    entries.push_back(entry);
  }
  return {{"method", o.refine.empty() ? "none" : o.refine},
          {"target", o.refine_target},
          {"perturb", std::vector<double>{m.perturb_translation, m.perturb_rotation_deg}},
          {"seed", o.seed},
          {"frames", entries},
          {"ate_before", err.ate_given},
          {"ate_after", err.ate_used},
          {"seconds", run.registerSeconds()}};
}

nlohmann::json odometryJson(const KittiMappingOptions& m, const KittiMappingRun& run) {
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t k = 0; k < run.odometry.size(); ++k) {
    const OdometryResult& r = run.odometry[k];
    frames.push_back({{"frame", m.frames[k]},
                      {"correspondences", r.correspondences},
                      {"iterations", r.iterations},
                      {"threshold", r.threshold},
                      {"degenerate_directions", r.degenerate_directions}});
  }
  return {{"frames", frames}, {"seconds", run.registerSeconds()}};
}

nlohmann::json occupancyJson(const KittiMappingRun& run) {
  const LogOddsMap* map = run.mapper->occupancy();
  if (map == nullptr) return nullptr;
  return {{"resolution", map->resolution()},
          {"occupied_voxels", map->occupiedVoxels()},
          {"free_voxels", map->freeVoxels()},
          {"seconds", run.occupancySeconds()}};
}

}  // namespace

std::string kittiReport(const KittiOptions& o, const KittiMappingOptions& m,
                        const KittiMappingRun& run, const MapImage& image,
                        const KittiReportFigures& figures) {
  const bool odometry = m.mapper.odometry;
  const KittiMappingTotals& tot = run.totals;
  const std::size_t occupied = run.mapper->occupiedCells();
  if (o.format != "json") {
    Table tab({"frames", "points_read", "points_kept", "map_width", "map_height", "occupied_cells",
               "seconds"});
    tab.addRow({std::to_string(m.frames.size()), std::to_string(tot.points_read),
                std::to_string(tot.points_kept), std::to_string(image.width),
                std::to_string(image.height), std::to_string(occupied), fixed(figures.total_s, 3)});
    return renderTable(tab, o.format);
  }
  nlohmann::json reg_summary = nullptr;
  if (!odometry && (!o.refine.empty() || !o.perturb.empty())) {
    reg_summary = registrationJson(o, m, run);
  }
  return nlohmann::json({{"frames", m.frames.size()},
                         {"poses", o.poses},
                         {"odometry", odometry ? odometryJson(m, run) : nlohmann::json(nullptr)},
                         {"registration", reg_summary},
                         {"points_read", tot.points_read},
                         {"points_kept", tot.points_kept},
                         {"points_mapped", tot.points_mapped},
                         {"global_points", figures.global_points},
                         {"seconds",
                          {{"load", tot.load_s},
                           {"transform", tot.transform_s},
                           {"map", tot.map_s},
                           {"write", figures.write_s},
                           {"total", figures.total_s}}},
                         {"map",
                          {{"plane", o.map_plane},
                           {"resolution", o.mapper.map_resolution},
                           {"width", image.width},
                           {"height", image.height},
                           {"origin", {image.origin_x, image.origin_y, 0.0}},
                           {"cells_with_hits", run.mapper->map().cells()},
                           {"occupied_cells", occupied},
                           {"min_hits", o.min_hits}}},
                         {"occupancy", occupancyJson(run)}})
             .dump(2) +
         "\n";
}

}  // namespace metricmap::cli
