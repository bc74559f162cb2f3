#include "odometry_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "metricmap/sequence/odometry_timing.h"
#include "table.h"

namespace metricmap::cli {
namespace {

nlohmann::json statsJson(const ErrorStatistics& s) {
  return {{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median}, {"max", s.max}};
}

nlohmann::json frameJson(const OdometryFrame& f, const Eigen::Isometry3d& p, bool first) {
  nlohmann::json row = {{"frame", f.index},
                        {"scan", f.name},
                        {"pose", std::vector<double>()},
                        {"ms", f.ms},
                        {"iterations", f.result.iterations},
                        {"coarse_iterations", f.result.coarse_iterations},
                        {"correspondences", f.result.correspondences},
                        {"source_points", f.result.points_source},
                        {"threshold", f.result.threshold},
                        {"degenerate_directions", f.result.degenerate_directions},
                        {"restarted", f.result.restarted},
                        {"support", f.result.support},
                        {"hypothesis", f.result.hypothesis},
                        {"step", first ? nlohmann::json(nullptr) : nlohmann::json(f.step_m)},
                        {"pose_file_difference", nullptr}};
  for (int i = 0; i < 12; ++i) row["pose"].push_back(p.matrix()(i / 4, i % 4));
  if (f.diff_m) {
    row["pose_file_difference"] = {{"translation", *f.diff_m}, {"rotation_deg", *f.diff_deg}};
  }
  return row;
}

}  // namespace

std::string odometryReport(const std::string& format, const std::string& profile,
                           const RangeOptions& ranges, const SourceInfo& info, const OdometryRun& r,
                           std::chrono::steady_clock::time_point t_start) {
  Table tab({"frame", "x", "y", "z", "step_m", "ms", "iterations", "pairs", "diff_m", "diff_deg"});
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const OdometryFrame& f = r.frames[k];
    const Eigen::Isometry3d& p = r.trajectory.poses[k];
    tab.addRow({std::to_string(f.index), fixed(p.translation().x(), 3),
                fixed(p.translation().y(), 3), fixed(p.translation().z(), 3), fixed(f.step_m, 3),
                fixed(f.ms, 1), std::to_string(f.result.iterations),
                std::to_string(f.result.correspondences), f.diff_m ? fixed(*f.diff_m, 4) : "-",
                f.diff_deg ? fixed(*f.diff_deg, 3) : "-"});
    rows.push_back(frameJson(f, p, k == 0));
  }
  const double median_ms = medianFrameMs(r.frames);
  const LidarOdometryConfig& c = r.config;
  // Where the range window and voxel came from: the profile, and the options that replaced its
  // values (stated, never silent).
  std::vector<std::string> given;
  if (ranges.max_range) given.emplace_back("--max-range");
  if (ranges.min_range) given.emplace_back("--min-range");
  if (ranges.voxel_size) given.emplace_back("--voxel-size");
  const std::string profile_name = !profile.empty() ? profile : info.conventions.default_profile;
  std::string origin = "profile " + profile_name + (r.profile.used ? " from the first scan" : "");
  for (std::size_t i = 0; i < given.size(); ++i) origin += (i == 0 ? "; given: " : ", ") + given[i];
  if (format == "json") {
    const nlohmann::json settings = {{"profile", r.profile.used ? "auto" : "given"},
                                     {"profile_name", profile_name},
                                     {"given_options", given},
                                     {"max_range", c.max_range},
                                     {"min_range", c.min_range},
                                     {"voxel_size", c.voxel_size},
                                     {"coarse_voxel_size", c.coarse_voxel_size},
                                     {"max_threshold", c.max_threshold},
                                     {"deskew", r.deskewed}};
    nlohmann::json j = {
        {"source", info.path},
        {"source_kind", info.kind},
        {"convention", r.convention},
        {"world_frame", worldFrameName(r.world)},
        {"up_in_first_scan",
         r.up ? nlohmann::json({r.up->up.x(), r.up->up.y(), r.up->up.z()}) : nlohmann::json()},
        {"settings", settings},
        {"frames", rows},
        {"pose_file", info.reference_path.empty() ? nlohmann::json(nullptr)
                                                  : nlohmann::json(info.reference_path)},
        {"deskew", r.deskewed},
        {"median_ms_per_scan", median_ms},
        {"seconds", {{"load", r.read_seconds}, {"total", secondsSince(t_start)}}}};
    j["rpe_per_frame"] = nullptr;
    if (r.rpe) {
      j["rpe_per_frame"] = {{"translation_m", statsJson(r.rpe->translation_stats)},
                            {"rotation_deg", statsJson(r.rpe->rotation_stats)}};
    }
    j["failed_steps"] = nullptr;
    if (r.failed_steps) {
      const StepFailures& s = *r.failed_steps;
      j["failed_steps"] = {{"max_translation_m", s.limits.max_translation},
                           {"max_rotation_deg", s.limits.max_rotation_deg},
                           {"steps", s.steps},
                           {"count", s.failed.size()},
                           {"failed_from_pose", s.failed}};
    }
    return j.dump(2) + "\n";
  }
  std::string report = renderTable(tab, format);
  char line[512];
  std::snprintf(line, sizeof line,
                "settings: max_range %g m, min_range %g m, voxel %g m, coarse voxel %g m, "
                "threshold cap %g m, deskew %s (%s)\n",
                c.max_range, c.min_range, c.voxel_size, c.coarse_voxel_size, c.max_threshold,
                r.deskewed ? "on" : "off", origin.c_str());
  report += line;
  if (r.up) {
    std::snprintf(line, sizeof line,
                  "world frame: level (z up along the first scan's ground normal %.4f %.4f %.4f, "
                  "%.2f deg from the sensor's z; sensor %.2f m above the ground)\n",
                  r.up->up.x(), r.up->up.y(), r.up->up.z(),
                  std::acos(std::min(1.0, r.up->up.z())) * 180.0 / M_PI, r.up->height);
  } else {
    std::snprintf(line, sizeof line, "world frame: %s\n",
                  r.convention == "sensor" ? "first-scan (the first scan's sensor frame)"
                                           : r.convention.c_str());
  }
  report += line;
  if (r.rpe) {
    const ErrorStatistics& t = r.rpe->translation_stats;
    const ErrorStatistics& a = r.rpe->rotation_stats;
    std::snprintf(line, sizeof line,
                  "difference from %s per frame: translation median %.4f m, max %.4f m, "
                  "rmse %.4f m; rotation median %.3f deg, max %.3f deg\n",
                  info.reference_path.c_str(), t.median, t.max, t.rmse, a.median, a.max);
    report += line;
  }
  if (r.failed_steps) {
    const StepFailures& s = *r.failed_steps;
    std::snprintf(line, sizeof line, "failed steps (off by > %g m or > %g deg): %zu of %zu\n",
                  s.limits.max_translation, s.limits.max_rotation_deg, s.failed.size(), s.steps);
    report += line;
  }
  std::snprintf(line, sizeof line,
                "%zu frames, median %.1f ms per scan (load excluded), %.2f s in all\n",
                r.frames.size(), median_ms, secondsSince(t_start));
  return report + line;
}

}  // namespace metricmap::cli
