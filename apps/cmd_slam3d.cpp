// metricmap slam3d SOURCE: 3D LiDAR SLAM with loop closure (slam3d/slam3d.h) over any scan
// source; the trajectory, the maps rebuilt from the source at the final poses, the pose graph,
// a top view and a report.
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/array_writers.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/map_picture.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/output_set.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/occupancy/octomap_quiet.h"
#include "metricmap/posegraph/g2o_io.h"
#include "metricmap/sequence/sequence_mapper.h"
#include "metricmap/slam3d/slam3d_run.h"
#include "sequence_options.h"
#include "set_options.h"
#include "slam3d_report.h"

namespace metricmap::cli {
namespace {

struct Slam3DOptions {
  SourceOptions source;
  RangeOptions ranges;
  std::string profile, pose_format = "tum", pcd_format = "binary", format = "table";
  std::string out_poses, out_cloud, out_map, out_bt, out_graph, out_png;
  double map_resolution = 0.1, octomap_resolution = 0.2, cloud_voxel = 0.2;
  bool no_deskew = false;
  std::vector<std::string> set;
  Slam3DConfig config;
};

double peakMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

Eigen::Vector2d onPlane(const Eigen::Vector3d& p, MapPlane plane) {
  if (plane == MapPlane::XZ) return {p.x(), p.z()};
  if (plane == MapPlane::YZ) return {p.y(), p.z()};
  return {p.x(), p.y()};
}

ScanMapperConfig mapperConfig(const Slam3DOptions& o, const SourceInfo& info) {
  ScanMapperConfig c;
  const MapConvention convention = mapConvention(info);
  c.up = convention.up;
  c.plane = convention.plane;
  c.min_range = o.config.min_range;
  c.max_range = o.config.max_range;
  c.voxel = o.cloud_voxel;
  c.keep_global_cloud = !o.out_cloud.empty();
  if (!o.out_bt.empty()) {
    LogOddsParams p;
    p.resolution = o.octomap_resolution;
    c.occupancy = p;
  }
  if (!o.out_map.empty() || !o.out_png.empty()) {
    Occupancy2DConfig g;
    g.params.resolution = o.map_resolution;
    c.occupancy_2d = g;
  }
  return c;
}

void run(const Slam3DOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<ScanSource> source = openSource(o.source);
  Slam3DRunOptions ro;
  ro.slam = o.config;
  ro.odometry.frames = selectedFrames(o.source, *source);
  applyRangeOptions(o.ranges, o.profile, source->info(), ro.odometry.config, ro.odometry.profile);
  ro.odometry.deskew = o.no_deskew ? DeskewMode::Off : DeskewMode::Auto;
  const bool progress = isatty(STDERR_FILENO) != 0;
  Slam3DRun r = runSlam3D(*source, ro, [&](std::size_t done, std::size_t total, const Slam3D& s) {
    if (progress && ((done - 1) % 50 == 0 || done == total))
      std::fprintf(stderr, "\rslam3d: scan %zu of %zu, %zu loops, %.0f s   %s", done, total,
                   s.verifiedLoops(), secondsSince(start), done == total ? "\n" : "");
  });
  if (!o.out_poses.empty() && o.pose_format == "tum" && !r.trajectory.hasStamps())
    throw InputError(o.source.path +
                     ": its scans have no time stamps: --pose-format tum needs "
                     "them (use --pose-format kitti)");
  const auto t_maps = std::chrono::steady_clock::now();
  const ScanMapperConfig mc = mapperConfig(o, source->info());
  std::unique_ptr<SequenceMapper> mapper;
  if (!o.out_cloud.empty() || !o.out_bt.empty() || !o.out_map.empty() || !o.out_png.empty()) {
    mapper = std::make_unique<SequenceMapper>(*source, mc);
    mapper->build(r.map_poses, r.frames);
  }
  Slam3DTimes times;
  times.maps = secondsSince(t_maps);
  OutputSet outputs;  // committed once the report is printed
  const auto t_write = std::chrono::steady_clock::now();
  if (!o.out_poses.empty())
    writeTextAtomic(outputs.stage(o.out_poses), o.pose_format == "tum"
                                                    ? formatTumTrajectory(r.trajectory)
                                                    : formatKittiTrajectory(r.trajectory));
  if (!o.out_graph.empty()) writeG2o(outputs.stage(o.out_graph), r.slam->graph());
  if (!o.out_cloud.empty())
    savePcdAtomic(outputs.stage(o.out_cloud), mapper->maps().globalCloud(),
                  parsePcdFormat(o.pcd_format));
  if (!o.out_bt.empty()) writeOctomapQuietly(*mapper->maps().occupancy(), outputs.stage(o.out_bt));
  if (!o.out_map.empty() || !o.out_png.empty()) {
    const MapServerImage image = mapper->maps().occupancy2D()->trinaryImage();
    if (image.width == 0) throw InputError(o.source.path + ": the 2D map is empty");
    if (!o.out_map.empty()) {
      MapServerFiles files = mapServerFiles(o.out_map);
      files.preview_png.clear();
      writeMapServer(image, files, outputs);
    }
    if (!o.out_png.empty()) {
      std::vector<Eigen::Vector2d> path;
      for (const Eigen::Isometry3d& p : r.map_poses)
        path.push_back(onPlane(p.translation(), mc.plane));
      std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> links;
      for (const Slam3DLoop& l : r.slam->loopChecks())
        if (l.check.accepted) links.emplace_back(path[l.from], path[l.to]);
      const int scale = image.width * image.height < 4000000 ? 2 : 1;
      writePng(outputs.stage(o.out_png), image.width * scale, image.height * scale, 3,
               drawMapPicture(image, scale, path, links));
    }
  }
  times.write = secondsSince(t_write);
  times.total = secondsSince(start);
  const auto& st = r.trajectory.stamps;
  times.span = st.size() > 1 ? st.back() - st.front() : 0.0;
  times.peak_mib = peakMiB();
  emitSlam3DReport(o.source.path, r, times, o.format, outputs);
}

}  // namespace

void addSlam3DCommand(CLI::App& app) {
  auto o = std::make_shared<Slam3DOptions>();
  CLI::App* sub = app.add_subcommand(
      "slam3d", "3D LiDAR SLAM with loop closure on any scan source: trajectory, maps, pose graph");
  addSourceOptions(*sub, o->source);
  addRangeOptions(*sub, o->ranges, o->profile);
  sub->add_flag("--no-deskew", o->no_deskew, "Never deskew, even with per-point times");
  sub->add_option("--out-poses", o->out_poses,
                  "Trajectory: the sensor in the frame of the first scan (KITTI: camera 0)")
      ->check(kOutputFile);
  sub->add_option("--pose-format", o->pose_format,
                  "tum (stamp tx ty tz qx qy qz qw) or kitti (12 numbers)")
      ->check(CLI::IsMember({"kitti", "tum"}))
      ->capture_default_str();
  sub->add_option("--out-cloud", o->out_cloud, "Global cloud at the final poses (PCD)")
      ->check(kOutputFile);
  addPcdFormatOption(*sub, o->pcd_format);
  sub->add_option("--cloud-voxel", o->cloud_voxel,
                  "Average the global cloud in cells of this size (m, 0: off)")
      ->check(finiteIn(0, 1000))
      ->capture_default_str();
  sub->add_option("--out-map", o->out_map, "2D occupancy map (map_server PGM + YAML)")
      ->check(kOutputFile);
  sub->add_option("--map-resolution", o->map_resolution, "2D map cell (m)")
      ->check(kCellEdge)
      ->capture_default_str();
  sub->add_option("--out-bt", o->out_bt, "3D log-odds map (OctoMap .bt)")->check(kOutputFile);
  sub->add_option("--octomap-resolution", o->octomap_resolution, "3D map voxel (m)")
      ->check(kCellEdge)
      ->capture_default_str();
  sub->add_option("--out-graph", o->out_graph, "Pose graph (g2o)")->check(kOutputFile);
  sub->add_option("--out-png", o->out_png,
                  "Top view: 2D map, trajectory (blue), verified loops (red)")
      ->check(kOutputFile);
  sub->add_option("--set", o->set, "Any SLAM parameter as NAME=VALUE (docs/SLAM3D.md)");
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    refuseIgnored(*sub, "--pose-format", !o->out_poses.empty(), "without --out-poses");
    refuseIgnored(*sub, "--pcd-format", !o->out_cloud.empty(), "without --out-cloud");
    refuseIgnored(*sub, "--cloud-voxel", !o->out_cloud.empty(), "without --out-cloud");
    refuseIgnored(*sub, "--octomap-resolution", !o->out_bt.empty(), "without --out-bt");
    refuseIgnored(*sub, "--map-resolution", !o->out_map.empty() || !o->out_png.empty(),
                  "without --out-map or --out-png");
    applySetOptions(*sub, o->set, {}, [&o](const std::string& n, const std::string& v) {
      setSlam3DParameter(o->config, n, v);
    });
    validateSetOptions([&o] { validateSlam3DConfig(o->config); });
    checkRangeOptions(*sub, o->ranges);
    checkSourceOptions(*sub, o->source);
    RolePaths outputs = {{"--out-poses", o->out_poses},
                         {"--out-cloud", o->out_cloud},
                         {"--out-bt", o->out_bt},
                         {"--out-graph", o->out_graph},
                         {"--out-png", o->out_png}};
    if (!o->out_map.empty()) {
      const MapServerFiles map = mapServerFiles(o->out_map);
      outputs.push_back({"--out-map", map.pgm});
      outputs.push_back({"--out-map (its .yaml)", map.yaml});
    }
    requireDistinctFiles(sourceInputs(o->source), outputs);
    requireExtension("--out-poses", o->out_poses, {".txt", ".tum"}, "a trajectory");
    requireExtension("--out-cloud", o->out_cloud, {".pcd"}, "a PCD cloud");
    requireExtension("--out-map", o->out_map, {".pgm"}, "a map_server PGM");
    requireExtension("--out-bt", o->out_bt, {".bt"}, "an OctoMap .bt");
    requireExtension("--out-graph", o->out_graph, {".g2o"}, "a g2o graph");
    requireExtension("--out-png", o->out_png, {".png"}, "a PNG picture");
    run(*o);
  });
}

}  // namespace metricmap::cli
