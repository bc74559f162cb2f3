// metricmap localize LOG --map MAP.yaml: the robot found in a saved map without an initial pose,
// then tracked scan by scan (localization/localizer_2d.h); poses of the localised scans, a
// picture, a report with every scan's status.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "localize_3d_command.h"
#include "localize_report.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/common/pose_2d_spatial.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/evaluation/trajectory_order.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/array_writers.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/map_picture.h"
#include "metricmap/io/map_server_reader.h"
#include "metricmap/io/output_set.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/localization/localize_2d_run.h"
#include "metricmap/localization/localizer_2d_parameters.h"
#include "metricmap/localization/point_map_3d.h"
#include "sequence_options.h"
#include "set_options.h"

namespace metricmap::cli {
namespace {

struct LocalizeOptions {
  SourceOptions source;
  bool initial_pose_given = false;
  std::string map, initial_pose, out_poses, pose_format = "tum", out_png, format = "table";
  Localizer2DConfig config;
  Localizer3DConfig config3d;
  std::vector<std::string> set;
};

/// The 3D run: the options that mean something for a 3D map onto its configuration.
void run3D(const CLI::App& app, const LocalizeOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (!o.set.empty()) throw UsageError("--set names 2D parameters; a 3D map takes none");
  refuseIgnored(app, "--out-png", false, "with a 3D map (a 2D map's picture)");
  Localize3DCommand c;
  c.source = o.source;
  c.map = o.map;
  c.out_poses = o.out_poses;
  c.pose_format = o.pose_format;
  c.format = o.format;
  c.config = o.config3d;
  if (app.count("--max-range") > 0) c.config.max_range = o.config.max_range;
  if (app.count("--min-score") > 0)
    c.config.verify.min_structure_overlap = o.config.global_min_score;
  if (app.count("--min-margin") > 0) c.config.global_min_margin = o.config.global_min_margin;
  if (app.count("--track-min-score") > 0) c.config.track_min_overlap = o.config.track_min_score;
  if (app.count("--lost-after") > 0)
    c.config.lost_after_weak_scans = o.config.lost_after_weak_scans;
  try {
    validateLocalizer3DConfig(c.config);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (o.initial_pose_given) {
    std::vector<double> v;
    try {
      v = parseDoubleList(o.initial_pose, "--initial-pose");
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    if (v.size() != 6)
      throw UsageError("--initial-pose: a 3D map takes x,y,z,roll,pitch,yaw (m, rad), not " +
                       std::to_string(v.size()) + " numbers");
    c.initial = poseFromXyzRpy(v);
  }
  runLocalize3DCommand(c, start);
}

/// --set NAME=VALUE onto the configuration, then the whole of it checked.
/// Each name once, not also given by its own option, the initial pose's windows only with
/// --initial-pose.
void applySettings(const CLI::App& app, LocalizeOptions& o) {
  static const OwnOptions own = {{"max_range", "--max-range"},
                                 {"global_min_score", "--min-score"},
                                 {"global_min_margin", "--min-margin"},
                                 {"track_min_score", "--track-min-score"},
                                 {"lost_after_weak_scans", "--lost-after"}};
  const std::vector<std::string> names =
      applySetOptions(app, o.set, own, [&o](const std::string& n, const std::string& v) {
        setLocalizer2DParameter(o.config, n, v);
      });
  for (const std::string& name : names)
    if (name.rfind("initial_", 0) == 0 && !o.initial_pose_given)
      throw UsageError("--set " + name + " has no effect without --initial-pose");
  validateSetOptions([&o] { validateLocalizer2DConfig(o.config); });
}

/// The localised scans' poses with their stamps (map frame).
Trajectory localisedTrajectory(const Localize2DRun& run) {
  Trajectory t;
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    if (!run.results[k].localised()) continue;
    t.poses.push_back(spatialPose(run.results[k].pose));
    t.stamps.push_back(run.stamps[k]);
  }
  return t;
}

void writeOutputs(const LocalizeOptions& o, const Map2D& map, const Localize2DRun& run,
                  OutputSet& outputs) {
  const Trajectory t = localisedTrajectory(run);
  if (!o.out_poses.empty()) {
    // In stamp order (raw logs deliver scans out of order); KITTI rows carry no stamp.
    Trajectory rows = o.pose_format == "tum" ? inStampOrder(t) : t;
    if (o.pose_format == "kitti") rows.stamps.clear();
    writeTextAtomic(outputs.stage(o.out_poses), o.pose_format == "tum"
                                                    ? formatTumTrajectory(rows)
                                                    : formatKittiTrajectory(rows));
  }
  if (o.out_png.empty()) return;
  const MapServerImage image = mapServerImage(map);
  std::vector<Eigen::Vector2d> path;  // in the grid frame, where the image is drawn
  for (const Eigen::Isometry3d& p : t.poses) path.push_back(map.toGrid(p.translation().head<2>()));
  const int scale = image.width * image.height < 4000000 ? 2 : 1;
  writePng(outputs.stage(o.out_png), image.width * scale, image.height * scale, 3,
           drawMapPicture(image, scale, path, {}));
}

void run(const LocalizeOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<Pose2D> initial;
  if (o.initial_pose_given) {
    std::vector<double> v;
    try {
      v = parseDoubleList(o.initial_pose, "--initial-pose");
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    if (v.size() != 3)
      throw UsageError("--initial-pose: give x,y,yaw (m, m, rad), not " + std::to_string(v.size()) +
                       " numbers");
    initial = Pose2D{v[0], v[1], v[2]};
  }
  const Map2D map = loadMapServer(o.map);
  const double map_seconds = secondsSince(start);
  if (initial) {
    try {
      validateInitialPose(map, *initial);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--initial-pose: ") + e.what());
    }
  }
  std::unique_ptr<ScanSource> source = openSource(o.source);
  const SourceInfo& info = source->info();
  if (!info.planar)
    throw InputError(o.source.path +
                     ": localize needs 2D laser scans (a CARMEN log) with a "
                     "map_server map; this is a " +
                     info.kind + " source of 3D scans");
  const std::vector<std::size_t> frames = selectedFrames(o.source, *source);
  const bool progress = isatty(STDERR_FILENO) != 0;
  Localize2DRun result =
      runLocalize2D(*source, frames, map, o.config, initial,
                    [progress](std::size_t done, std::size_t total, const Localizer2D& l) {
                      if (progress && ((done - 1) % 250 == 0 || done == total))
                        std::fprintf(stderr, "\rlocalize: scan %zu of %zu, %zu localised%s", done,
                                     total, l.stats().localised, done == total ? "\n" : "");
                    });
  if (!o.out_poses.empty() && result.localizer->stats().localised == 0)
    throw InputError(o.source.path + ": no scan was localised in " + o.map +
                     ": nothing to write to --out-poses");
  if (!o.out_poses.empty() && o.pose_format == "tum") {
    for (std::size_t k = 0; k < result.results.size(); ++k)
      if (result.results[k].localised() && !std::isfinite(result.stamps[k]))
        throw InputError(o.source.path + ": scan " + std::to_string(frames[k]) +
                         " has no time stamp: --pose-format tum needs them");
    try {
      inStampOrder(localisedTrajectory(result));
    } catch (const std::invalid_argument& e) {
      throw InputError(o.source.path + ": " + e.what() +
                       "; --pose-format tum needs one pose per stamp");
    }
  }
  OutputSet outputs;  // committed once the report is printed
  const auto t_write = std::chrono::steady_clock::now();
  writeOutputs(o, map, result, outputs);
  LocalizeTimes times;
  times.map = map_seconds;
  times.write = secondsSince(t_write);
  times.total = secondsSince(start);
  double lo = INFINITY, hi = -INFINITY;
  for (double s : result.stamps)
    if (std::isfinite(s)) lo = std::min(lo, s), hi = std::max(hi, s);
  times.log = hi > lo ? hi - lo : 0.0;
  emitLocalizeReport(o.source.path, o.map, frames, result, times, o.format, outputs);
}

}  // namespace

void addLocalizeCommand(CLI::App& app) {
  auto o = std::make_shared<LocalizeOptions>();
  CLI::App* sub = app.add_subcommand(
      "localize",
      "Find and track a robot in a saved map (2D: a CARMEN log in a map_server map; 3D: "
      "3D scans in a PCD/PLY/OctoMap map)");
  addSourceOptions(*sub, o->source);
  sub->add_option(
         "--map", o->map,
         "The map: a map_server YAML (and the PGM it names), or a 3D map (.pcd, .ply, .bt, .ot)")
      ->required();
  sub->add_option_function<std::string>(
      "--initial-pose",
      [o](const std::string& v) {
        o->initial_pose = v;
        o->initial_pose_given = true;
      },
      "x,y,yaw in the map's frame (m, m, rad), or x,y,z,roll,pitch,yaw for a 3D map: "
      "searched around it instead of the whole map");
  sub->add_option("--out-poses", o->out_poses,
                  "Poses of the localised scans in the map's frame, with the scans' stamps")
      ->check(kOutputFile);
  sub->add_option("--pose-format", o->pose_format,
                  "tum (stamp tx ty tz qx qy qz qw) or kitti (12 numbers)")
      ->check(CLI::IsMember({"tum", "kitti"}))
      ->capture_default_str();
  sub->add_option("--out-png", o->out_png, "Picture: the map with the localised path (blue)")
      ->check(kOutputFile);
  Localizer2DConfig& c = o->config;
  const std::vector<ParameterSpec> schema = localizer2DParameterSchema();
  sub->add_option("--max-range", c.max_range, "Beams beyond are dropped (m)")
      ->check(declaredRange(schema, "max_range"))
      ->capture_default_str();
  sub->add_option("--min-score", c.global_min_score,
                  "Score a global fix must reach (mean probability of the scan's cells)")
      ->check(declaredRange(schema, "global_min_score"))
      ->capture_default_str();
  sub->add_option("--min-margin", c.global_min_margin,
                  "A global fix must beat the best distinct pose's score by this much")
      ->check(declaredRange(schema, "global_min_margin"))
      ->capture_default_str();
  sub->add_option("--track-min-score", c.track_min_score,
                  "Tracked scans scoring below are weak (not reported)")
      ->check(declaredRange(schema, "track_min_score"))
      ->capture_default_str();
  sub->add_option("--lost-after", c.lost_after_weak_scans,
                  "Weak scans in a row after which the robot is lost (global search again)")
      ->check(declaredRange(schema, "lost_after_weak_scans"))
      ->capture_default_str();
  sub->add_option("--set", o->set,
                  "Any localisation parameter, NAME=VALUE (repeatable; names in "
                  "docs/LOCALIZATION.md)");
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    checkSourceOptions(*sub, o->source);
    refuseIgnored(*sub, "--pose-format", !o->out_poses.empty(), "without --out-poses");
    if (isPointMap3DPath(o->map)) {
      requireExtension("--out-poses", o->out_poses, {".tum", ".txt"}, "a pose file");
      RolePaths inputs = sourceInputs(o->source);
      inputs.push_back({"--map", o->map});
      requireDistinctFiles(inputs, {{"--out-poses", o->out_poses}});
      return run3D(*sub, *o);
    }
    applySettings(*sub, *o);
    const auto dot = o->map.find_last_of('.');
    const std::string ext = dot == std::string::npos ? "" : o->map.substr(dot);
    if (ext != ".yaml" && ext != ".yml")
      throw UsageError("--map '" + quoteForMessage(o->map) +
                       "': give a map_server YAML (.yaml or .yml; not its image) or a 3D map "
                       "(.pcd, .ply, .bt, .ot)");
    requireExtension("--out-poses", o->out_poses, {".tum", ".txt"}, "a pose file");
    requireExtension("--out-png", o->out_png, {".png"}, "a PNG picture");
    RolePaths inputs = sourceInputs(o->source);
    inputs.push_back({"--map", o->map});
    inputs.push_back({"--map's image", readMapServerYaml(o->map).image_path});
    requireDistinctFiles(inputs, {{"--out-poses", o->out_poses}, {"--out-png", o->out_png}});
    run(*o);
  });
}

}  // namespace metricmap::cli
