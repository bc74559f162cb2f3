// metricmap kitti ROOT --sequence NN: scans + poses -> global cloud and a 2D occupancy map.
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>

#include <unistd.h>

#include <pcl/common/transforms.h>
#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/kitti/kitti_sequence.h"
#include "metricmap/kitti/occupancy_map_2d.h"
#include "metricmap/kitti/scan_registration.h"
#include "table.h"

namespace metricmap::cli {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

struct KittiOptions {
  std::string root, sequence = "00", frames, world = "camera", out_cloud, out_map;
  std::string pcd_format = "binary", map_plane = "xz", format = "table", refine, perturb;
  std::string refine_target = "map", out_poses;
  unsigned seed = 1;
  long long first = -1, count = 0, min_hits = 1;
  double min_range = 0.0, max_range = std::numeric_limits<double>::infinity();
  double min_height = -std::numeric_limits<double>::infinity();
  double max_height = std::numeric_limits<double>::infinity();
  double voxel = 0.0, map_resolution = 0.1;
};

std::vector<std::size_t> selectFrames(const KittiOptions& o) {
  if (!o.frames.empty() && o.first >= 0) {
    throw CLI::ValidationError("frames", "give --frames or --first/--count, not both");
  }
  if (!o.frames.empty()) return parseFrameList(o.frames);
  if (o.first < 0 || o.count <= 0) {
    throw CLI::ValidationError("frames", "give --frames LIST or --first F --count N (N > 0)");
  }
  std::vector<std::size_t> f;
  for (long long i = 0; i < o.count; ++i) f.push_back(static_cast<std::size_t>(o.first + i));
  return f;
}

Cloud voxelize(const Cloud::Ptr& cloud, double voxel) {
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setOrigin(GridOrigin::WorldAligned);
  grid.setCellSize(static_cast<float>(voxel));
  grid.setInputCloud(cloud);
  Cloud out;
  grid.filter(out);
  return out;
}

void run(const KittiOptions& o) {
  const auto t_start = std::chrono::steady_clock::now();
  const std::vector<std::size_t> frames = selectFrames(o);
  const KittiSequence seq{o.root, o.sequence};
  for (std::size_t f : frames) {  // every scan must exist before any work is done
    if (access(seq.scan(f).c_str(), R_OK) != 0) throw InputError(seq.scan(f) + ": missing frame");
  }
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const std::size_t last = *std::max_element(frames.begin(), frames.end());
  const std::vector<Eigen::Isometry3d> poses = readKittiPoses(seq.poses(), last + 1);
  const KittiWorld world = o.world == "velodyne" ? KittiWorld::Velodyne : KittiWorld::Camera;
  // The world's up axis: -y for KITTI's camera frame, z for the velodyne frame.
  const Eigen::Vector3f up =
      world == KittiWorld::Camera ? Eigen::Vector3f(0, -1, 0) : Eigen::Vector3f(0, 0, 1);
  OccupancyMap2D map(o.map_resolution, parseMapPlane(o.map_plane));
  auto global = std::make_shared<Cloud>();
  std::uint64_t read = 0, kept = 0, mapped = 0;
  double load_s = 0, transform_s = 0, map_s = 0;
  const bool progress = isatty(STDERR_FILENO) != 0;
  // Registration: frame 0 anchors the map; later frames start from their (optionally
  // perturbed) pose and are aligned to the map built so far.
  double perturb_t = 0.0, perturb_r = 0.0;
  if (!o.perturb.empty()) {
    const auto comma = o.perturb.find(',');
    perturb_t = std::stod(o.perturb.substr(0, comma));
    perturb_r = std::stod(o.perturb.substr(comma + 1));
  }
  std::mt19937 rng(o.seed);
  RefineParams refine;
  if (!o.refine.empty()) refine.method = parseRefineMethod(o.refine);
  auto target = std::make_shared<Cloud>();
  nlohmann::json registration = nlohmann::json::array();
  double reg_s = 0.0, sq_before = 0.0, sq_after = 0.0;
  std::string poses_text;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    auto t = std::chrono::steady_clock::now();
    Cloud scan;
    loadCloud(seq.scan(frames[k]), scan);
    read += scan.size();
    load_s += secondsSince(t);

    t = std::chrono::steady_clock::now();
    auto world_scan = std::make_shared<Cloud>();
    world_scan->reserve(scan.size());
    for (const auto& p : scan) {
      const double r = p.getVector3fMap().norm();
      if (r >= o.min_range && r <= o.max_range) world_scan->push_back(p);
    }
    world_scan->width = static_cast<std::uint32_t>(world_scan->size());
    world_scan->height = 1;
    const Eigen::Isometry3d truth = kittiScanToWorld(poses[frames[k]], tr, world);
    Eigen::Isometry3d pose = truth;
    if ((perturb_t > 0.0 || perturb_r > 0.0) && k > 0)
      pose = perturbPose(truth, perturb_t, perturb_r, rng);
    if (!o.refine.empty() || !o.perturb.empty()) {
      const PoseError before = poseError(truth, pose);
      nlohmann::json entry = {
          {"frame", frames[k]},
          {"error_before",
           {{"translation", before.translation}, {"rotation_deg", before.rotation_deg}}}};
      Eigen::Isometry3d refined = pose;
      if (!o.refine.empty() && k > 0) {
        const auto t_reg = std::chrono::steady_clock::now();
        const RefineResult r = refineScanPose(registrationCloud(*world_scan), target, pose, refine);
        reg_s += secondsSince(t_reg);
        refined = r.scan_to_world;
        const PoseError correction = poseError(pose, refined);
        entry["correction"] = {{"translation", correction.translation},
                               {"rotation_deg", correction.rotation_deg}};
        entry["converged"] = r.converged;
        entry["fitness"] = r.fitness;
      }
      const PoseError after = poseError(truth, refined);
      entry["error_after"] = {{"translation", after.translation},
                              {"rotation_deg", after.rotation_deg}};
      sq_before += before.translation * before.translation;
      sq_after += after.translation * after.translation;
      registration.push_back(entry);
      pose = refined;
    }
    pcl::transformPointCloud(*world_scan, *world_scan, pose.matrix().cast<float>());
    if (!o.refine.empty() && (k == 0 || o.refine_target != "first")) {
      Cloud structure;
      pcl::transformPointCloud(*registrationCloud(scan), structure, pose.matrix().cast<float>());
      if (o.refine_target == "map") {
        *target += structure;
        *target = voxelize(target, 0.2);
      } else {
        *target = structure;
      }
    }
    if (!o.out_poses.empty()) {  // KITTI's convention: camera 0 poses, or velodyne ones
      const Eigen::Isometry3d out = world == KittiWorld::Camera ? pose * tr.inverse() : pose;
      for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 4; ++col) {
          char num[32];
          std::snprintf(num, sizeof num, "%.9e", out.matrix()(row, col));
          poses_text += (row || col ? " " : "") + std::string(num);
        }
      }
      poses_text += "\n";
    }
    if (o.voxel > 0.0) *world_scan = voxelize(world_scan, o.voxel);
    kept += world_scan->size();
    transform_s += secondsSince(t);

    t = std::chrono::steady_clock::now();
    Cloud band;
    for (const auto& p : *world_scan) {
      const float h = up.dot(p.getVector3fMap());
      if (h >= o.min_height && h <= o.max_height) band.push_back(p);
    }
    mapped += band.size();
    map.add(band);
    map_s += secondsSince(t);
    if (!o.out_cloud.empty()) *global += *world_scan;
    if (progress) {
      const double elapsed = secondsSince(t_start);
      std::fprintf(
          stderr, "\rframe %zu/%zu  %.1f M points/s  %.0f s left   ", k + 1, frames.size(),
          static_cast<double>(read) / elapsed / 1e6,
          elapsed / static_cast<double>(k + 1) * static_cast<double>(frames.size() - k - 1));
    }
  }
  if (progress) std::fprintf(stderr, "\n");

  auto t = std::chrono::steady_clock::now();
  if (!o.out_poses.empty()) writeTextAtomic(o.out_poses, poses_text);
  if (!o.out_cloud.empty()) {
    if (o.voxel > 0.0) *global = voxelize(global, o.voxel);
    savePcdAtomic(o.out_cloud, *global, parsePcdFormat(o.pcd_format));
  }
  const MapImage image = map.image();
  std::size_t occupied = 0;
  if (!o.out_map.empty()) {
    const std::string stem = o.out_map.substr(0, o.out_map.find_last_of('.'));
    occupied = writeMapServer(image, static_cast<std::uint32_t>(o.min_hits), o.out_map,
                              stem + "_preview.png", stem + "_heat.png");
  } else {
    for (auto h : image.hits) occupied += h >= static_cast<std::uint64_t>(o.min_hits) && h > 0;
  }
  const double write_s = secondsSince(t);

  nlohmann::json reg_summary = nullptr;
  if (!registration.empty()) {
    const double n = static_cast<double>(registration.size());
    reg_summary = {{"method", o.refine.empty() ? "none" : o.refine},
                   {"target", o.refine_target},
                   {"perturb", {perturb_t, perturb_r}},
                   {"seed", o.seed},
                   {"frames", registration},
                   {"ate_before", std::sqrt(sq_before / n)},
                   {"ate_after", std::sqrt(sq_after / n)},
                   {"seconds", reg_s}};
  }
  if (o.format == "json") {
    emit(nlohmann::json({{"frames", frames.size()},
                         {"registration", reg_summary},
                         {"points_read", read},
                         {"points_kept", kept},
                         {"points_mapped", mapped},
                         {"global_points", global->size()},
                         {"seconds",
                          {{"load", load_s},
                           {"transform", transform_s},
                           {"map", map_s},
                           {"write", write_s},
                           {"total", secondsSince(t_start)}}},
                         {"map",
                          {{"plane", o.map_plane},
                           {"resolution", o.map_resolution},
                           {"width", image.width},
                           {"height", image.height},
                           {"origin", {image.origin_x, image.origin_y, 0.0}},
                           {"cells_with_hits", map.cells()},
                           {"occupied_cells", occupied},
                           {"min_hits", o.min_hits}}}})
                 .dump(2) +
             "\n",
         "");
    return;
  }
  Table tab({"frames", "points_read", "points_kept", "map_width", "map_height", "occupied_cells",
             "seconds"});
  tab.addRow({std::to_string(frames.size()), std::to_string(read), std::to_string(kept),
              std::to_string(image.width), std::to_string(image.height), std::to_string(occupied),
              fixed(secondsSince(t_start), 3)});
  emitTable(tab, o.format);
}

}  // namespace

void addKittiCommand(CLI::App& app) {
  auto o = std::make_shared<KittiOptions>();
  CLI::App* sub =
      app.add_subcommand("kitti", "KITTI scans + poses -> global cloud, 2D occupancy map");
  sub->add_option("root", o->root, "KITTI odometry root (sequences/, poses/)")->required();
  sub->add_option("--sequence", o->sequence, "Sequence number")->capture_default_str();
  sub->add_option("--frames", o->frames, "Frames, e.g. 0-5,15");
  sub->add_option("--first", o->first, "First frame")->check(kCount);
  sub->add_option("--count", o->count, "Number of frames")->check(kCount);
  sub->add_option("--world", o->world, "camera (KITTI's, y down) or velodyne (z up)")
      ->check(CLI::IsMember({"camera", "velodyne"}))
      ->capture_default_str();
  sub->add_option("--min-range", o->min_range, "Drop returns closer than this (m), e.g. the car")
      ->check(kFiniteNonNegative);
  sub->add_option("--max-range", o->max_range, "Drop returns further than this (m)")
      ->check(kFinitePositive);
  sub->add_option("--min-height", o->min_height, "Map only points at or above this height (m)");
  sub->add_option("--max-height", o->max_height, "Map only points at or below this height (m)");
  sub->add_option("--voxel", o->voxel, "Per-scan and global voxel size (m), 0: off")
      ->check(kFiniteNonNegative);
  sub->add_option("--out-cloud", o->out_cloud, "Write the global cloud (.pcd)");
  addPcdFormatOption(*sub, o->pcd_format);
  sub->add_option("--out-map", o->out_map,
                  "map_server map: M.pgm + M.yaml, with M_preview.png and M_heat.png");
  sub->add_option("--map-plane", o->map_plane, "Projection plane")
      ->check(CLI::IsMember({"xz", "xy", "yz"}))
      ->capture_default_str();
  sub->add_option("--map-resolution", o->map_resolution, "Map cell size (m)")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_option("--min-hits", o->min_hits, "Hits that make a cell occupied")
      ->check(kCount & kFinitePositive)
      ->capture_default_str();
  sub->add_option("--refine", o->refine,
                  "Align each scan to --refine-target (pcl::IterativeClosestPoint or "
                  "pcl::GeneralizedIterativeClosestPoint), starting from its pose")
      ->check(CLI::IsMember({"icp", "gicp"}));
  sub->add_option("--refine-target", o->refine_target,
                  "map: the refined scans so far; previous: the last scan; first: frame 0 only")
      ->check(CLI::IsMember({"map", "previous", "first"}))
      ->capture_default_str();
  sub->add_option("--out-poses", o->out_poses,
                  "Write the poses used (refined, perturbed or given), one 3x4 row-major line "
                  "per frame as in poses/NN.txt (velodyne poses with --world velodyne)");
  sub->add_option("--perturb", o->perturb,
                  "t,r: move each pose after frame 0 by t metres and turn it by r degrees, "
                  "random directions (seeded)")
      ->check(CLI::Validator(
          [](std::string& s) {
            const auto comma = s.find(',');
            char* end = nullptr;
            if (comma == std::string::npos) return std::string("expected t,r");
            const double t = std::strtod(s.substr(0, comma).c_str(), &end);
            if (*end != '\0' || !std::isfinite(t) || t < 0) return std::string("bad translation");
            const double r = std::strtod(s.substr(comma + 1).c_str(), &end);
            if (*end != '\0' || !std::isfinite(r) || r < 0) return std::string("bad rotation");
            return std::string();
          },
          "T,R"));
  sub->add_option("--seed", o->seed, "Random seed for --perturb")->capture_default_str();
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o] { run(*o); });
}

}  // namespace metricmap::cli
