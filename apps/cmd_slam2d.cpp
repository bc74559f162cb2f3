// metricmap slam2d LOG: 2D laser SLAM with submaps and loop closure (slam/slam_2d.h); the
// trajectory in TUM form, the map (map_server), the pose graph (g2o), a picture, a report.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/parse_number.h"
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
#include "metricmap/slam/slam_2d_overlay.h"
#include "metricmap/slam/slam_2d_run.h"
#include "sequence_options.h"
#include "slam2d_options.h"
#include "slam2d_report.h"

namespace metricmap::cli {
namespace {

struct Slam2DOptions {
  SourceOptions source;
  std::string out_poses, out_map, out_graph, out_png, format = "table";
  Slam2DOptionValues slam;
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
  const Slam2DOverlay overlay = slam2DOverlay(slam);
  const int scale = image.width * image.height < 4000000 ? 2 : 1;
  writePng(outputs.stage(o.out_png), image.width * scale, image.height * scale, 3,
           drawMapPicture(image, scale, overlay.path, overlay.links));
}

void run(const Slam2DOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<ScanSource> source = openSource(o.source);
  const SourceInfo& info = source->info();
  if (!info.planar)
    throw InputError(o.source.path + ": slam2d needs 2D laser scans (a CARMEN log); this is a " +
                     info.kind + " source of 3D scans");
  const std::vector<std::size_t> frames = selectedFrames(o.source, *source);
  Slam2DConfig config = o.slam.config;
  if (o.slam.no_loops)
    config.loop_every_n_nodes = config.wide_every_n_nodes = static_cast<std::size_t>(-1);
  const bool progress = isatty(STDERR_FILENO) != 0;
  Slam2DRun run = runSlam2D(
      *source, frames, config, o.source.path,
      [progress](std::size_t done, std::size_t total, const Slam2D& slam) {
        if (progress && ((done - 1) % 250 == 0 || done == total))
          std::fprintf(stderr, "\rslam2d: scan %zu of %zu, %zu nodes, %zu loop closures%s", done,
                       total, slam.stats().nodes, slam.loops().size(), done == total ? "\n" : "");
      });
  if (progress && frames.empty()) std::fprintf(stderr, "\n");
  const Slam2D& slam = *run.slam;
  Trajectory& trajectory = run.trajectory;
  if (slam.map().knownCells() == 0)
    throw InputError(o.source.path + ": no beam within --max-range " +
                     plainNumber(config.max_range) + " m: the map is empty");
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
  emitSlam2DReport(o.source.path, slam,
                   {run.read_seconds, write_seconds, total, stampSpan(trajectory)}, o.format,
                   outputs);
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
  addSlam2DOptions(*sub, o->slam);
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    checkSourceOptions(*sub, o->source);
    applySlam2DOptions(*sub, o->slam);
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
