// metricmap slam2d LOG: 2D laser SLAM with submaps and loop closure (slam/slam_2d.h); the
// trajectory in TUM form, the map (map_server), the pose graph (g2o), a picture, a report.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/common/pose_2d_spatial.h"
#include "metricmap/evaluation/trajectory_order.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/array_writers.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/map_picture.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/output_set.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/posegraph/g2o_io.h"
#include "metricmap/slam/slam_2d.h"
#include "metricmap/slam/slam_2d_parameters.h"
#include "sequence_options.h"

namespace metricmap::cli {
namespace {

struct Slam2DOptions {
  SourceOptions source;
  std::string out_poses, out_map, out_graph, out_png, format = "table";
  Slam2DConfig config;
  std::vector<std::string> set;  ///< NAME=VALUE
  bool no_loops = false;
};

void writeOutputs(const Slam2DOptions& o, const Slam2D& slam, const Trajectory& trajectory,
                  OutputSet& outputs) {
  if (!o.out_poses.empty())
    writeTextAtomic(outputs.stage(o.out_poses), formatTumTrajectory(trajectory));
  if (!o.out_graph.empty()) writeG2o(outputs.stage(o.out_graph), slam.graph());
  if (o.out_map.empty() && o.out_png.empty()) return;
  const MapServerImage image = slam.map().trinaryImage();
  if (!o.out_map.empty()) {
    MapServerFiles files = mapServerFiles(o.out_map);
    files.preview_png.clear();
    writeMapServer(image, files, outputs);
  }
  if (o.out_png.empty()) return;
  std::vector<Eigen::Vector2d> path;
  for (const auto& v : slam.graph().vertices()) path.emplace_back(v.pose.x, v.pose.y);
  // Loop edges from the centre of the submap matched (its anchor, the edge's other end, is
  // the submap's first node: lines from there cross the whole map).
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> links;
  const std::vector<Eigen::Vector2d> centres = slam.submapCentres();
  for (const LoopClosure2D& l : slam.loops()) {
    const Pose2D b = slam.graph().vertex(l.node).pose;
    links.emplace_back(centres[l.submap], Eigen::Vector2d(b.x, b.y));
  }
  const int scale = image.width * image.height < 4000000 ? 2 : 1;
  writePng(outputs.stage(o.out_png), image.width * scale, image.height * scale, 3,
           drawMapPicture(image, scale, path, links));
}

/// --set NAME=VALUE onto the configuration: each name once, not also given by its own option,
/// no loop parameter with --no-loop-closure; the whole configuration valid.
void applySettings(const CLI::App& app, Slam2DOptions& o) {
  static const std::vector<std::pair<std::string, std::string>> own = {
      {"map_resolution", "--map-resolution"},
      {"resolution", "--resolution"},
      {"max_range", "--max-range"},
      {"scans_per_submap", "--scans-per-submap"},
      {"loop_min_score", "--loop-min-score"},
      {"loop_linear_window", "--loop-window"},
      {"loop_angular_window_deg", "--loop-angle"}};
  std::vector<std::string> seen;
  for (const std::string& s : o.set) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set: '" + quoteForMessage(s) + "' is not NAME=VALUE");
    const std::string name = s.substr(0, eq);
    try {
      setSlam2DParameter(o.config, name, s.substr(eq + 1));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--set: ") + e.what());
    }
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      throw UsageError("--set: " + name + " is given twice");
    seen.push_back(name);
    for (const auto& [field, option] : own)
      if (field == name && app.count(option) > 0)
        throw UsageError("--set " + name + " and " + option + " set the same parameter");
    if (o.no_loops && (name.rfind("loop_", 0) == 0 || name.rfind("wide_", 0) == 0 ||
                       name == "branch_and_bound_depth"))
      throw UsageError("--set " + name + " has no effect with --no-loop-closure");
  }
  try {
    validateSlam2DConfig(o.config);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--set: ") + e.what());
  }
}

void run(const Slam2DOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<ScanSource> source = openSource(o.source);
  const SourceInfo& info = source->info();
  if (!info.planar)
    throw InputError(o.source.path + ": slam2d needs 2D laser scans (a CARMEN log); this is a " +
                     info.kind + " source of 3D scans");
  const std::vector<std::size_t> frames = selectedFrames(o.source, *source);
  Slam2DConfig config = o.config;

  if (o.no_loops)
    config.loop_every_n_nodes = config.wide_every_n_nodes = static_cast<std::size_t>(-1);
  Slam2D slam(config, planarPose(info.sensor_to_base));
  Trajectory trajectory;
  double read_seconds = 0.0;
  const bool progress = isatty(STDERR_FILENO) != 0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    Scan scan = source->scan(frames[k]);
    read_seconds += secondsSince(t0);
    if (!scan.laser) throw InputError(scan.name + ": not a 2D laser scan");
    std::optional<Pose2D> odometry;
    if (scan.odometry) odometry = planarPose(*scan.odometry);
    try {
      slam.addScan(*scan.laser, odometry, scan.stamp);
    } catch (const CapacityError& e) {  // the maps outgrew the budget: name the scan
      throw CapacityError(scan.name + ": " + e.what());
    } catch (const std::invalid_argument& e) {  // odometry beyond reach: name the scan
      throw InputError(scan.name + ": " + e.what());
    }
    trajectory.stamps.push_back(scan.stamp);
    if (progress && (k % 250 == 0 || k + 1 == frames.size()))
      std::fprintf(stderr, "\rslam2d: scan %zu of %zu, %zu nodes, %zu loop closures", k + 1,
                   frames.size(), slam.stats().nodes, slam.loops().size());
  }
  if (progress) std::fprintf(stderr, "\n");
  try {
    slam.finish();
  } catch (const CapacityError& e) {
    throw CapacityError(o.source.path + ": " + e.what());
  }
  if (slam.map().knownCells() == 0)
    throw InputError(o.source.path + ": no beam within --max-range " +
                     plainNumber(config.max_range) + " m: the map is empty");
  for (const Pose2D& p : slam.trajectory()) trajectory.poses.push_back(spatialPose(p));
  if (!std::all_of(trajectory.stamps.begin(), trajectory.stamps.end(),
                   [](double s) { return std::isfinite(s); }))
    trajectory.stamps.clear();
  if (!o.out_poses.empty() && !trajectory.hasStamps())
    throw InputError(o.source.path +
                     ": its scans have no time stamps: --out-poses (TUM) needs them");
  if (!o.out_poses.empty()) {
    try {  // TUM rows in stamp order: raw logs deliver scans out of order
      trajectory = inStampOrder(trajectory);
    } catch (const std::invalid_argument& e) {
      throw InputError(o.source.path + ": " + e.what() +
                       "; --out-poses (TUM) needs one pose per stamp");
    }
  }
  OutputSet outputs;  // committed once the report is printed
  const auto t_write = std::chrono::steady_clock::now();
  writeOutputs(o, slam, trajectory, outputs);
  const double write_seconds = secondsSince(t_write), total = secondsSince(start);
  const Slam2DStats& s = slam.stats();
  const double span =
      trajectory.hasStamps()
          ? *std::max_element(trajectory.stamps.begin(), trajectory.stamps.end()) -
                *std::min_element(trajectory.stamps.begin(), trajectory.stamps.end())
          : 0.0;
  const nlohmann::json j = {
      {"input", o.source.path},
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
       {{"read", read_seconds},
        {"local", s.local_seconds},
        {"insert", s.insert_seconds},
        {"loop_search", s.loop_seconds},
        {"optimize", s.optimize_seconds},
        {"map", s.map_seconds},
        {"write", write_seconds},
        {"total", total}}},
      {"log_seconds", span},
      {"real_time_factor", total > 0 ? span / total : 0.0}};
  if (o.format == "json") return emit(j.dump(2) + "\n", outputs);
  char text[1024];
  std::snprintf(
      text, sizeof text,
      "%s: %zu scans, %zu nodes, %zu submaps\n"
      "loop closures: %zu found in %zu searches, %zu rejected as outliers; %zu optimisations, "
      "final chi2 %.6g\n"
      "map: %zu occupied, %zu free cells of %.3g m\n"
      "time: %.2f s (read %.2f, local %.2f, insert %.2f, loop search %.2f, optimise "
      "%.2f, map %.2f, write %.2f) for %.6g s of log: %.3gx real time\n",
      o.source.path.c_str(), s.scans, s.nodes, s.submaps, s.loops_found, s.loop_searches,
      s.loops_rejected, s.optimizations, s.final_chi2, slam.map().occupiedCells(),
      slam.map().freeCells(), config.map.resolution, total, read_seconds, s.local_seconds,
      s.insert_seconds, s.loop_seconds, s.optimize_seconds, s.map_seconds, write_seconds, span,
      total > 0 ? span / total : 0.0);
  emit(text, outputs);
}

}  // namespace

void addSlam2DCommand(CLI::App& app) {
  auto o = std::make_shared<Slam2DOptions>();
  CLI::App* sub = app.add_subcommand(
      "slam2d", "2D laser SLAM with loop closure on a CARMEN log: trajectory, map, pose graph");
  addSourceOptions(*sub, o->source);
  sub->add_option("--out-poses", o->out_poses,
                  "Trajectory in TUM form: every scan at the log's stamp, in stamp order")
      ->check(kOutputFile);
  sub->add_option("--out-map", o->out_map, "Occupancy map (map_server PGM + YAML)")
      ->check(kOutputFile);
  sub->add_option("--out-graph", o->out_graph, "Pose graph (g2o)")->check(kOutputFile);
  sub->add_option("--out-png", o->out_png, "Picture: map, trajectory (blue), loop closures (red)")
      ->check(kOutputFile);
  Slam2DConfig& c = o->config;
  sub->add_option("--map-resolution", c.map.resolution, "Cell of the map (m)")
      ->check(finiteIn(0.005, 10))
      ->capture_default_str();
  sub->add_option("--resolution", c.resolution, "Cell of the submaps (m)")
      ->check(finiteIn(0.005, 10))
      ->capture_default_str();
  sub->add_option("--max-range", c.max_range, "Beams beyond: free space only (m)")
      ->check(finiteIn(0.1, 1000))
      ->capture_default_str();
  sub->add_option("--scans-per-submap", c.scans_per_submap, "Nodes a submap receives")
      ->check(countIn(1, 100000))
      ->capture_default_str();
  sub->add_option("--loop-min-score", c.loop_min_score, "Score a loop closure must reach")
      ->check(finiteIn(0.01, 0.99))
      ->capture_default_str();
  sub->add_option("--loop-window", c.loop_linear_window, "Loop search half-width (m)")
      ->check(finiteIn(0.05, 100))
      ->capture_default_str();
  sub->add_option("--loop-angle", c.loop_angular_window_deg, "Loop search half-angle (deg)")
      ->check(finiteIn(0.1, 180))
      ->capture_default_str();
  sub->add_option("--set", o->set,
                  "Any SLAM parameter, NAME=VALUE (repeatable; names in docs/SLAM.md)");
  sub->add_flag("--no-loop-closure", o->no_loops, "Local SLAM only (no loop search)");
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    checkSourceOptions(*sub, o->source);
    for (const char* opt : {"--loop-min-score", "--loop-window", "--loop-angle"})
      refuseIgnored(*sub, opt, !o->no_loops, "with --no-loop-closure");
    applySettings(*sub, *o);
    if (o->config.max_range <= o->config.min_range)
      throw UsageError("--max-range must exceed the minimum range");
    const MapServerFiles map = mapServerFiles(o->out_map.empty() ? "x.pgm" : o->out_map);
    RolePaths outputs = {
        {"--out-poses", o->out_poses}, {"--out-graph", o->out_graph}, {"--out-png", o->out_png}};
    if (!o->out_map.empty()) {
      outputs.push_back({"--out-map", map.pgm});
      outputs.push_back({"--out-map (its .yaml)", map.yaml});
    }
    requireDistinctFiles(sourceInputs(o->source), outputs);
    requireExtension("--out-map", o->out_map, {".pgm"}, "a map_server PGM");
    requireExtension("--out-graph", o->out_graph, {".g2o"}, "a g2o graph");
    requireExtension("--out-poses", o->out_poses, {".tum", ".txt"}, "a TUM trajectory");
    requireExtension("--out-png", o->out_png, {".png"}, "a PNG picture");
    run(*o);
  });
}

}  // namespace metricmap::cli
