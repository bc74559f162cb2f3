#include "localize_3d_command.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "cli_common.h"
#include "localize_report.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/evaluation/trajectory_order.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/localization/localize_3d_run.h"
#include "metricmap/localization/point_map_3d.h"

namespace metricmap::cli {
namespace {

Trajectory localisedTrajectory(const Localize3DRun& run) {
  Trajectory t;
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    if (!run.results[k].localised()) continue;
    t.poses.push_back(run.results[k].pose);
    t.stamps.push_back(run.stamps[k]);
  }
  return t;
}

}  // namespace

Eigen::Isometry3d poseFromXyzRpy(const std::vector<double>& v) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  p.linear() = (Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(v[4], Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return p;
}

void runLocalize3DCommand(const Localize3DCommand& c, std::chrono::steady_clock::time_point start) {
  const PointMap3D map = loadPointMap3D(c.map);
  const double map_seconds = secondsSince(start);
  std::unique_ptr<ScanSource> source = openSource(c.source);
  const SourceInfo& info = source->info();
  if (info.planar)
    throw InputError(c.source.path + ": a " + info.kind + " source of 2D laser scans; a 3D map (" +
                     c.map + ") needs 3D scans");
  const std::vector<std::size_t> frames = selectedFrames(c.source, *source);
  const bool progress = isatty(STDERR_FILENO) != 0;
  Localize3DRun result;
  try {
    result =
        runLocalize3D(*source, frames, map, c.config, c.initial,
                      [progress](std::size_t done, std::size_t total, const Localizer3D& l) {
                        if (progress && ((done - 1) % 50 == 0 || done == total))
                          std::fprintf(stderr, "\rlocalize: scan %zu of %zu, %zu localised%s", done,
                                       total, l.stats().localised, done == total ? "\n" : "");
                      });
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--initial-pose: ") + e.what());
  }
  if (!c.out_poses.empty() && result.localizer->stats().localised == 0)
    throw InputError(c.source.path + ": no scan was localised in " + c.map +
                     ": nothing to write to --out-poses");
  const Trajectory t = localisedTrajectory(result);
  if (!c.out_poses.empty() && c.pose_format == "tum") {
    for (std::size_t k = 0; k < result.results.size(); ++k)
      if (result.results[k].localised() && !std::isfinite(result.stamps[k]))
        throw InputError(c.source.path + ": scan " + std::to_string(frames[k]) +
                         " has no time stamp: --pose-format tum needs them");
    try {
      inStampOrder(t);
    } catch (const std::invalid_argument& e) {
      throw InputError(c.source.path + ": " + e.what() +
                       "; --pose-format tum needs one pose per stamp");
    }
  }
  OutputSet outputs;  // committed once the report is printed
  const auto t_write = std::chrono::steady_clock::now();
  if (!c.out_poses.empty()) {
    Trajectory rows = c.pose_format == "tum" ? inStampOrder(t) : t;
    if (c.pose_format == "kitti") rows.stamps.clear();
    writeTextAtomic(outputs.stage(c.out_poses), c.pose_format == "tum"
                                                    ? formatTumTrajectory(rows)
                                                    : formatKittiTrajectory(rows));
  }
  LocalizeTimes times;
  times.map = map_seconds;
  times.write = secondsSince(t_write);
  times.total = secondsSince(start);
  double lo = INFINITY, hi = -INFINITY;
  for (double s : result.stamps)
    if (std::isfinite(s)) lo = std::min(lo, s), hi = std::max(hi, s);
  times.log = hi > lo ? hi - lo : 0.0;
  emitLocalizeReport(c.source.path, c.map, frames, result, times, c.format, outputs);
}

}  // namespace metricmap::cli
