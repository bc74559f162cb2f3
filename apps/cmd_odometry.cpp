// metricmap odometry SOURCE: poses from the scans alone (runOdometry over any scan source),
// compared per frame with the source's reference poses when it has them.
#include <cstdio>
#include <memory>

#include <unistd.h>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/sequence/odometry_run.h"
#include "odometry_report.h"
#include "sequence_options.h"

namespace metricmap::cli {
namespace {

struct OdometryOptions {
  SourceOptions source;
  std::string out_poses, pose_format = "kitti", format = "table", profile, world = "first-scan";
  bool deskew_azimuth = false, no_deskew = false;
  RangeOptions ranges;
  unsigned threads = 0;
  double min_support = -1.0, support_distance = -1.0, prediction_rotation = -1.0;
  int hypothesis_count = -1;
};

void run(const OdometryOptions& o) {
  const auto t_start = std::chrono::steady_clock::now();
  std::unique_ptr<ScanSource> source = openSource(o.source);
  OdometryRunOptions ro;
  ro.frames = selectedFrames(o.source, *source);
  ro.config.threads = o.threads;
  ro.world = parseWorldFrame(o.world);
  if (o.min_support >= 0.0) ro.config.min_support = o.min_support;
  if (o.support_distance >= 0.0) ro.config.support_distance = o.support_distance;
  if (o.prediction_rotation >= 0.0) ro.config.prediction_rotation = o.prediction_rotation;
  if (o.hypothesis_count >= 0) ro.config.hypothesis_count = o.hypothesis_count;
  applyRangeOptions(o.ranges, o.profile, source->info(), ro.config, ro.profile);
  ro.profile.motion = o.min_support < 0.0 && o.prediction_rotation < 0.0;
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

  const std::string poses_text = o.pose_format == "tum" ? formatTumTrajectory(r.trajectory)
                                                        : formatKittiTrajectory(r.trajectory);
  const std::string report =
      odometryReport(o.format, o.profile, o.ranges, source->info(), r, t_start);
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
                  "frame (as poses/NN.txt), otherwise the sensor in the world of --world-frame")
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
  sub->add_option("--world-frame", o->world,
                  "World of the poses: level (z up along the first scan's ground normal, x/y "
                  "level) or first-scan (the first scan's sensor frame); KITTI keeps camera 0")
      ->check(CLI::IsMember({"level", "first-scan"}))
      ->capture_default_str();
  sub->add_option("--min-support", o->min_support,
                  "Try the motion hypotheses when fewer than this fraction of a scan's points "
                  "find a map point within a voxel (0: never, 1: every scan; default: 1 for scans "
                  "at least 0.3 s apart, else 0); given, it or --prediction-rotation replaces the "
                  "profile's motion model")
      ->check(CLI::Range(0.0, 1.0));
  sub->add_option("--support-distance", o->support_distance,
                  "Distance (m) at which the hypotheses' support is compared (0: the voxel)")
      ->check(kFiniteNonNegative);
  sub->add_option(
         "--prediction-rotation", o->prediction_rotation,
         "Share of the last motion's rotation the prediction repeats (1: constant "
         "velocity, 0: translation only; default: 0 for scans at least 0.3 s apart, else 1)")
      ->check(CLI::Range(0.0, 1.0));
  sub->add_option("--hypothesis-count", o->hypothesis_count,
                  "Hypotheses registered by ICP when they are tried (1..16)")
      ->check(CLI::Range(1, 16));
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    refuseIgnored(*sub, "--pose-format", !o->out_poses.empty(), "without --out-poses");
    if (o->deskew_azimuth && o->no_deskew) {
      throw CLI::ValidationError("--deskew", "cannot be given with --no-deskew");
    }
    checkRangeOptions(*sub, o->ranges);
    checkSourceOptions(*sub, o->source);
    requireDistinctFiles(sourceInputs(o->source), {{"--out-poses", o->out_poses}});
    // TUM rows go where a .tum name says they are; KITTI rows in .txt, as poses/NN.txt
    if (o->pose_format == "tum")
      requireExtension("--out-poses", o->out_poses, {".txt", ".tum"}, "TUM pose text");
    else
      requireExtension("--out-poses", o->out_poses, {".txt"}, "KITTI pose text");
    run(*o);
  });
}

}  // namespace metricmap::cli
