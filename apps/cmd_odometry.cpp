// metricmap odometry SOURCE: poses from the scans alone (runOdometry over any scan source),
// compared per frame with the source's reference poses when it has them.
#include <algorithm>
#include <cstdio>
#include <memory>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/sequence/odometry_run.h"
#include "sequence_options.h"
#include "table.h"

namespace metricmap::cli {
namespace {

struct OdometryOptions {
  SourceOptions source;
  std::string out_poses, pose_format = "kitti", format = "table", profile;
  bool deskew_azimuth = false, no_deskew = false;
  RangeOptions ranges;
  unsigned threads = 0;
};

nlohmann::json statsJson(const ErrorStatistics& s) {
  return {{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median}, {"max", s.max}};
}

void run(const OdometryOptions& o) {
  const auto t_start = std::chrono::steady_clock::now();
  std::unique_ptr<ScanSource> source = openSource(o.source);
  OdometryRunOptions ro;
  ro.frames = selectedFrames(o.source, *source);
  ro.config.threads = o.threads;
  applyRangeOptions(o.ranges, o.profile, source->info(), ro.config, ro.profile);
  ro.deskew = o.no_deskew        ? DeskewMode::Off
              : o.deskew_azimuth ? DeskewMode::Azimuth
                                 : DeskewMode::Auto;
  const bool progress = isatty(STDERR_FILENO) != 0;
  const OdometryRun r = runOdometryNamed(
      *source, ro, [&](const OdometryFrame& f, std::size_t done, std::size_t total) {
        if (!progress) return;
        std::fprintf(stderr, "\rframe %zu/%zu  %.1f ms/scan  %.0f s left   ", done, total, f.ms,
                     secondsSince(t_start) / done * static_cast<double>(total - done));
      });
  if (progress) std::fprintf(stderr, "\n");

  Table tab({"frame", "x", "y", "z", "step_m", "ms", "iterations", "pairs", "diff_m", "diff_deg"});
  nlohmann::json rows = nlohmann::json::array();
  std::vector<double> ms;
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const OdometryFrame& f = r.frames[k];
    const Eigen::Isometry3d& p = r.trajectory.poses[k];
    ms.push_back(f.ms);
    tab.addRow({std::to_string(f.index), fixed(p.translation().x(), 3),
                fixed(p.translation().y(), 3), fixed(p.translation().z(), 3), fixed(f.step_m, 3),
                fixed(f.ms, 1), std::to_string(f.result.iterations),
                std::to_string(f.result.correspondences), f.diff_m ? fixed(*f.diff_m, 4) : "-",
                f.diff_deg ? fixed(*f.diff_deg, 3) : "-"});
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
                          {"step", k ? nlohmann::json(f.step_m) : nlohmann::json(nullptr)},
                          {"pose_file_difference", nullptr}};
    for (int i = 0; i < 12; ++i) row["pose"].push_back(p.matrix()(i / 4, i % 4));
    if (f.diff_m) {
      row["pose_file_difference"] = {{"translation", *f.diff_m}, {"rotation_deg", *f.diff_deg}};
    }
    rows.push_back(row);
  }
  const std::string poses_text = o.pose_format == "tum" ? formatTumTrajectory(r.trajectory)
                                                        : formatKittiTrajectory(r.trajectory);
  std::sort(ms.begin(), ms.end());
  const double median_ms = ms[ms.size() / 2];
  const LidarOdometryConfig& c = r.config;
  // Where the range window and voxel came from: the profile, and the options that replaced its
  // values (stated, never silent).
  std::vector<std::string> given;
  if (o.ranges.max_range) given.emplace_back("--max-range");
  if (o.ranges.min_range) given.emplace_back("--min-range");
  if (o.ranges.voxel_size) given.emplace_back("--voxel-size");
  const std::string profile_name =
      !o.profile.empty() ? o.profile : (source->info().kind == "kitti" ? "kitti" : "auto");
  std::string origin = "profile " + profile_name + (r.profile.used ? " from the first scan" : "");
  for (std::size_t i = 0; i < given.size(); ++i) origin += (i == 0 ? "; given: " : ", ") + given[i];
  const nlohmann::json settings = {{"profile", r.profile.used ? "auto" : "given"},
                                   {"profile_name", profile_name},
                                   {"given_options", given},
                                   {"max_range", c.max_range},
                                   {"min_range", c.min_range},
                                   {"voxel_size", c.voxel_size},
                                   {"coarse_voxel_size", c.coarse_voxel_size},
                                   {"max_threshold", c.max_threshold},
                                   {"deskew", r.deskewed}};
  std::string report;
  if (o.format == "json") {
    nlohmann::json j = {{"source", source->info().path},
                        {"source_kind", source->info().kind},
                        {"convention", r.convention},
                        {"settings", settings},
                        {"frames", rows},
                        {"pose_file", source->info().reference_path.empty()
                                          ? nlohmann::json(nullptr)
                                          : nlohmann::json(source->info().reference_path)},
                        {"deskew", r.deskewed},
                        {"median_ms_per_scan", median_ms},
                        {"seconds", {{"load", r.read_seconds}, {"total", secondsSince(t_start)}}}};
    j["rpe_per_frame"] = nullptr;
    if (r.rpe) {
      j["rpe_per_frame"] = {{"translation_m", statsJson(r.rpe->translation_stats)},
                            {"rotation_deg", statsJson(r.rpe->rotation_stats)}};
    }
    report = j.dump(2) + "\n";
  } else {
    report = renderTable(tab, o.format);
    char line[512];
    std::snprintf(line, sizeof line,
                  "settings: max_range %g m, min_range %g m, voxel %g m, coarse voxel %g m, "
                  "threshold cap %g m, deskew %s (%s)\n",
                  c.max_range, c.min_range, c.voxel_size, c.coarse_voxel_size, c.max_threshold,
                  r.deskewed ? "on" : "off", origin.c_str());
    report += line;
    if (r.rpe) {
      const ErrorStatistics& t = r.rpe->translation_stats;
      const ErrorStatistics& a = r.rpe->rotation_stats;
      std::snprintf(line, sizeof line,
                    "difference from %s per frame: translation median %.4f m, max %.4f m, "
                    "rmse %.4f m; rotation median %.3f deg, max %.3f deg\n",
                    source->info().reference_path.c_str(), t.median, t.max, t.rmse, a.median,
                    a.max);
      report += line;
    }
    std::snprintf(line, sizeof line,
                  "%zu frames, median %.1f ms per scan (load excluded), %.2f s in all\n",
                  r.frames.size(), median_ms, secondsSince(t_start));
    report += line;
  }
  OutputSet outputs;  // committed once the report is printed
  if (!o.out_poses.empty()) writeTextAtomic(outputs.stage(o.out_poses), poses_text);
  emit(report, outputs);
}

}  // namespace

void addOdometryCommand(CLI::App& app) {
  auto o = std::make_shared<OdometryOptions>();
  CLI::App* sub = app.add_subcommand(
      "odometry", "LiDAR odometry from the scans alone (any scan source) -> poses");
  addSourceOptions(*sub, o->source);
  addRangeOptions(*sub, o->ranges, o->profile);
  sub->add_flag("--deskew", o->deskew_azimuth,
                "Deskew with times from the azimuth (a spinning sensor without per-point times); "
                "per-point times in the scans are used without this flag");
  sub->add_flag("--no-deskew", o->no_deskew, "Never deskew, even with per-point times");
  sub->add_option("--out-poses", o->out_poses,
                  "Write the poses: for KITTI camera 0 in the frame of camera 0 of the first "
                  "frame (as poses/NN.txt), otherwise the sensor in the frame of the first scan")
      ->check(kOutputFile);
  sub->add_option("--pose-format", o->pose_format,
                  "kitti (12 numbers) or tum (stamp tx ty tz qx qy qz qw)")
      ->check(CLI::IsMember({"kitti", "tum"}))
      ->capture_default_str();
  sub->add_option("--threads", o->threads,
                  "Threads for the scan-to-map pairing (0: all hardware threads); the poses do "
                  "not depend on it")
      ->check(countIn(0, 1024))
      ->capture_default_str();
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    refuseIgnored(*sub, "--pose-format", !o->out_poses.empty(), "without --out-poses");
    if (o->deskew_azimuth && o->no_deskew) {
      throw CLI::ValidationError("--deskew", "cannot be given with --no-deskew");
    }
    checkRangeOptions(*sub, o->ranges);
    checkSourceOptions(*sub, o->source);
    requireDistinctFiles(sourceInputs(o->source), {{"--out-poses", o->out_poses}});
    requireExtension("--out-poses", o->out_poses, {".txt"}, "pose text");
    run(*o);
  });
}

}  // namespace metricmap::cli
