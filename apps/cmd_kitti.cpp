// metricmap kitti ROOT --sequence NN: scans + poses -> global cloud and a 2D occupancy map.
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/output_set.h"
#include "metricmap/mapping/scan_mapper.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "octomap_quiet.h"
#include "table.h"

namespace metricmap::cli {
namespace {

/// --voxel: 0 (off) or a voxel edge a float holds as a normal number (the voxel grid is float:
/// 1e308 would become inf and be reported as such).
const CLI::Validator kVoxelSize(
    [](std::string& s) -> std::string {
      double v = 0.0;
      try {
        v = parseFiniteDouble(s, "--voxel");
      } catch (const std::invalid_argument&) {
        return "'" + quoteForMessage(s) + "' is not a finite decimal number";
      }
      if (v < 0.0) return "must be a finite number >= 0, got '" + quoteForMessage(s) + "'";
      if (v != 0.0 &&
          !(v >= std::numeric_limits<float>::min() && v <= std::numeric_limits<float>::max()))
        return "'" + quoteForMessage(s) +
               "' is outside the single-precision range (1.2e-38 to 3.4e38)";
      return std::string();
    },
    "VOXEL");

struct KittiOptions {
  std::string root, sequence = "00", frames, world = "camera", out_cloud, out_map;
  std::string pcd_format = "binary", map_plane = "xz", format = "table", refine, perturb;
  std::string refine_target = "map", out_poses, poses = "file";
  std::string out_octomap, out_trinary, band;  // 3D occupancy outputs
  double occupancy_resolution = 0.0, occupancy_max_range = LogOddsParams{}.max_range;
  unsigned seed = 1;
  long long first = -1, count = 0, min_hits = 1;
  ScanMapperConfig mapper;  // ranges, voxel, height band, map resolution: its defaults
};

std::vector<std::size_t> selectFrames(const KittiOptions& o) {
  if (!o.frames.empty() && o.first >= 0) {
    throw CLI::ValidationError("frames", "give --frames or --first/--count, not both");
  }
  if (o.frames.empty() && (o.first < 0 || o.count <= 0)) {
    throw CLI::ValidationError("frames", "give --frames LIST or --first F --count N (N > 0)");
  }
  if (o.frames.empty() && static_cast<unsigned long long>(o.count) > kMaxFrameList) {
    throw CLI::ValidationError("--count", "at most " + std::to_string(kMaxFrameList) + " frames");
  }
  if (!o.frames.empty()) return parseFramesOption(o.frames);
  try {
    return parseFrameList(std::to_string(o.first) + "-" + std::to_string(o.first + o.count - 1));
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--first", e.what());
  }
}

/// Largest --perturb: 100 m (a pose error no registration could undo) and 180 degrees (any
/// turn); beyond them a perturbed pose is not a physical one (1e308 m leaves the float range).
constexpr double kMaxPerturbMetres = 100.0, kMaxPerturbDegrees = 180.0;

/// Translation (m) and rotation (degrees) of --perturb T,R.
std::vector<double> perturbation(const std::string& text) {
  std::vector<double> v = parseDoubleList(text, "perturbation");
  if (v.size() != 2 || !(v[0] >= 0.0 && v[0] <= kMaxPerturbMetres) ||
      !(v[1] >= 0.0 && v[1] <= kMaxPerturbDegrees)) {
    throw std::invalid_argument(
        "--perturb: expected T,R with 0 <= T <= 100 (m) and 0 <= R <= "
        "180 (degrees), got '" +
        quoteForMessage(text) + "'");
  }
  return v;
}

ScanMapperConfig mapperConfig(const KittiOptions& o, KittiWorld world) {
  ScanMapperConfig c = o.mapper;
  // The world's up axis: -y for KITTI's camera frame, z for the velodyne frame.
  c.up = world == KittiWorld::Camera ? Eigen::Vector3f(0, -1, 0) : Eigen::Vector3f(0, 0, 1);
  c.plane = parseMapPlane(o.map_plane);
  c.min_hits = static_cast<std::uint32_t>(o.min_hits);
  c.keep_global_cloud = !o.out_cloud.empty();
  c.registration.enabled = !o.refine.empty();
  if (c.registration.enabled) c.registration.refine.method = parseRefineMethod(o.refine);
  c.registration.target = parseRegistrationTarget(o.refine_target);
  c.odometry = o.poses == "odometry";
  if (o.occupancy_resolution > 0.0) {
    LogOddsParams p;
    p.resolution = o.occupancy_resolution;
    p.max_range = o.occupancy_max_range;
    c.occupancy = p;
  } else if (!o.out_octomap.empty() || !o.out_trinary.empty()) {
    throw CLI::ValidationError("--occupancy-resolution",
                               "--out-octomap and --out-trinary need the 3D occupancy map");
  }
  if (!o.out_trinary.empty() && world != KittiWorld::Velodyne) {
    throw CLI::ValidationError("--out-trinary", "the band is along z: needs --world velodyne");
  }
  if (o.out_trinary.empty() != o.band.empty()) {
    throw CLI::ValidationError("--band", "--out-trinary and --band go together");
  }
  try {
    validateScanMapperConfig(c);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(e.what());  // option values: a usage error
  }
  return c;
}

nlohmann::json errorJson(const PoseError& e) {
  return {{"translation", e.translation}, {"rotation_deg", e.rotation_deg}};
}

nlohmann::json registrationJson(const KittiOptions& o, const std::vector<double>& perturb,
                                const std::vector<std::size_t>& frames,
                                const std::vector<FrameReport>& reports,
                                const TrajectoryError& err) {
  nlohmann::json entries = nlohmann::json::array();
  double seconds = 0.0;
  for (std::size_t k = 0; k < reports.size(); ++k) {
    nlohmann::json entry = {{"frame", frames[k]}, {"error_before", errorJson(err.given[k])}};
    if (reports[k].registered) {
      entry["correction"] = errorJson(poseError(reports[k].pose_given, reports[k].pose_used));
      entry["converged"] = reports[k].converged;
      entry["fitness"] = reports[k].fitness;
    }
    entry["error_after"] = errorJson(err.used[k]);
    entries.push_back(entry);
    seconds += reports[k].seconds_register;
  }
  return {{"method", o.refine.empty() ? "none" : o.refine},
          {"target", o.refine_target},
          {"perturb", perturb},
          {"seed", o.seed},
          {"frames", entries},
          {"ate_before", err.ate_given},
          {"ate_after", err.ate_used},
          {"seconds", seconds}};
}

nlohmann::json occupancyJson(const LogOddsMap* map, const std::vector<FrameReport>& reports) {
  if (map == nullptr) return nullptr;
  double seconds = 0.0;
  for (const FrameReport& r : reports) seconds += r.seconds_occupancy;
  return {{"resolution", map->resolution()},
          {"occupied_voxels", map->occupiedVoxels()},
          {"free_voxels", map->freeVoxels()},
          {"seconds", seconds}};
}

/// Options that would have no effect in this run are refused, never dropped (issue 24, class 6).
void refuseIgnoredOptions(const KittiOptions& o, const CLI::App& app) {
  const bool perturbs = !o.perturb.empty() && perturbation(o.perturb) != std::vector<double>{0, 0};
  refuseIgnored(
      app, "--seed", perturbs,
      "without --perturb T,R (T or R > 0): it seeds the perturbation's random directions");
  refuseIgnored(app, "--refine-target", !o.refine.empty(),
                "without --refine icp|gicp: it is what a refined scan is aligned to");
  refuseIgnored(app, "--target-voxel", !o.refine.empty() && o.refine_target == "map",
                "without --refine icp|gicp --refine-target map: it is the cell of the "
                "accumulated registration target");
  refuseIgnored(app, "--pcd-format", !o.out_cloud.empty(),
                "without --out-cloud: it is the encoding of the PCD written there");
  refuseIgnored(app, "--occupancy-max-range", o.occupancy_resolution > 0.0,
                "without --occupancy-resolution: it cuts the beams of the 3D occupancy map");
  refuseIgnored(app, "--occupancy-resolution",
                !o.out_octomap.empty() || !o.out_trinary.empty() || o.format == "json",
                "without --out-octomap, --out-trinary or --format json: the 3D map would be "
                "built and shown nowhere");
  refuseIgnored(app, "--count", o.frames.empty(),
                "with --frames: it counts frames from --first; give --frames or --first/--count");
  // The range and height windows, named as given (`1e2`, not `100.000000`).
  const auto quoted = [&app](const char* option, double value) {
    const std::string text = givenText(app, option);
    return std::string(option) + " '" + (text.empty() ? plainNumber(value) : text) + "'";
  };
  const ScanMapperConfig& m = o.mapper;
  if (m.min_range > m.max_range) {
    throw UsageError(quoted("--min-range", m.min_range) + " exceeds " +
                     quoted("--max-range", m.max_range) +
                     ": no return lies between the min range and the max range");
  }
  if (m.min_height > m.max_height) {
    throw UsageError(quoted("--min-height", m.min_height) + " exceeds " +
                     quoted("--max-height", m.max_height) +
                     ": no point lies between the min height and the max height");
  }
}

void run(const KittiOptions& o, const CLI::App& app) {
  const auto t_start = std::chrono::steady_clock::now();
  refuseIgnoredOptions(o, app);
  const std::vector<std::size_t> frames = selectFrames(o);
  if (o.poses == "odometry" && !o.perturb.empty()) {
    throw CLI::ValidationError("--perturb",
                               "moves poses from the pose file; not with --poses odometry");
  }
  const std::vector<double> perturb =
      o.perturb.empty() ? std::vector<double>{0.0, 0.0} : perturbation(o.perturb);
  const KittiWorld world = o.world == "velodyne" ? KittiWorld::Velodyne : KittiWorld::Camera;
  const ScanMapperConfig config = mapperConfig(o, world);
  {
    std::vector<std::pair<std::string, std::string>> outputs = {{"--out-poses", o.out_poses},
                                                                {"--out-cloud", o.out_cloud}};
    if (!o.out_map.empty()) {
      const MapServerFiles files = mapServerFiles(o.out_map);
      outputs.insert(outputs.end(), {{"--out-map", files.pgm},
                                     {"--out-map (its .yaml)", files.yaml},
                                     {"--out-map (its _preview.png)", files.preview_png},
                                     {"--out-map (its _heat.png)", files.heat_png}});
    }
    if (!o.out_octomap.empty()) outputs.push_back({"--out-octomap", o.out_octomap});
    if (!o.out_trinary.empty()) {
      const MapServerFiles files = mapServerFiles(o.out_trinary);
      outputs.insert(outputs.end(),
                     {{"--out-trinary", files.pgm}, {"--out-trinary (its .yaml)", files.yaml}});
    }
    requireDistinctFiles(kittiInputs(o.root, o.sequence, frames, o.poses != "odometry"), outputs);
    requireExtension("--out-cloud", o.out_cloud, {".pcd"}, "a PCD cloud");
    requireExtension("--out-map", o.out_map, {".pgm"}, "a map_server PGM with its YAML");
    requireExtension("--out-poses", o.out_poses, {".txt"}, "KITTI pose text");
    requireExtension("--out-octomap", o.out_octomap, {".bt", ".ot"}, "an OctoMap file");
    requireExtension("--out-trinary", o.out_trinary, {".pgm"}, "a map_server PGM with its YAML");
  }
  const KittiSequence seq{o.root, o.sequence};
  for (std::size_t f : frames) {  // every scan must exist before any work is done
    if (access(seq.scan(f).c_str(), R_OK) != 0) throw InputError(seq.scan(f) + ": missing frame");
  }
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const std::size_t last = *std::max_element(frames.begin(), frames.end());
  const bool odometry = o.poses == "odometry";  // no pose file needed, none read
  const std::vector<Eigen::Isometry3d> poses =
      odometry ? std::vector<Eigen::Isometry3d>() : readKittiPoses(seq.poses(), last + 1);
  ScanMapperConfig with_origin = config;
  // Odometry poses start at the first frame's velodyne; the world is its camera 0 or itself.
  if (odometry && world == KittiWorld::Camera) with_origin.odometry_origin = tr;
  ScanMapper mapper(with_origin);
  nlohmann::json odometry_frames = nlohmann::json::array();

  std::mt19937 rng(o.seed);
  std::vector<FrameReport> reports;
  std::vector<Eigen::Isometry3d> truths;
  std::uint64_t read = 0, kept = 0, mapped = 0;
  double load_s = 0, transform_s = 0, map_s = 0;
  const bool progress = isatty(STDERR_FILENO) != 0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    auto t = std::chrono::steady_clock::now();
    pcl::PointCloud<pcl::PointXYZ> scan;
    loadCloud(seq.scan(frames[k]), scan);
    load_s += secondsSince(t);
    try {
      if (odometry) {
        reports.push_back(mapper.addScan(scan));
        const OdometryResult& r = mapper.lastOdometry();
        odometry_frames.push_back({{"frame", frames[k]},
                                   {"correspondences", r.correspondences},
                                   {"iterations", r.iterations},
                                   {"threshold", r.threshold},
                                   {"degenerate_directions", r.degenerate_directions}});
      } else {
        truths.push_back(kittiScanToWorld(poses[frames[k]], tr, world));
        Eigen::Isometry3d pose = truths.back();
        if ((perturb[0] > 0.0 || perturb[1] > 0.0) && k > 0) {
          pose = perturbPose(pose, perturb[0], perturb[1], rng);
        }
        reports.push_back(mapper.addScan(scan, pose));
      }
    } catch (const InputError& e) {
      throw InputError(seq.scan(frames[k]) + ": " + e.what());
    }
    const FrameReport& r = reports.back();
    read += r.points_read;
    kept += r.points_kept;
    mapped += r.points_mapped;
    transform_s += r.seconds_transform + r.seconds_register;
    map_s += r.seconds_map;
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
  const MapImage image = mapper.map().image();
  if (!o.out_map.empty() && image.width == 0) {
    throw InputError("the map is empty: no point fell within the range and height bands");
  }
  requireOccupiedCells(image, static_cast<std::uint32_t>(o.min_hits), o.out_map);
  const pcl::PointCloud<pcl::PointXYZ> global = mapper.globalCloud();
  OutputSet outputs;  // every output or none, committed once the report is printed
  if (!o.out_poses.empty()) {
    std::vector<Eigen::Isometry3d> out;
    for (const Eigen::Isometry3d& p : mapper.poses()) out.push_back(kittiPoseOfScan(p, tr, world));
    writeTextAtomic(outputs.stage(o.out_poses), formatKittiPoses(out));
  }
  if (!o.out_cloud.empty()) {
    savePcdAtomic(outputs.stage(o.out_cloud), global, parsePcdFormat(o.pcd_format));
  }
  const LogOddsMap* occupancy = mapper.occupancy();
  if (!o.out_octomap.empty()) writeOctomapQuietly(*occupancy, outputs.stage(o.out_octomap));
  if (!o.out_trinary.empty()) {
    const std::vector<double> band = parseDoubleList(o.band, "--band");
    const TrinaryMap t = projectBand(*occupancy, band.at(0), band.at(1));
    MapServerFiles files = mapServerFiles(o.out_trinary);
    files.preview_png.clear();
    writeMapServer(mapServerImage(t), files, outputs);
  }
  if (!o.out_map.empty()) {
    writeMapServer(mapServerImage(image, mapper.config().min_hits), mapServerFiles(o.out_map),
                   outputs, heatImage(image));
  }
  const std::size_t occupied = mapper.occupiedCells();
  const double write_s = secondsSince(t);

  nlohmann::json reg_summary = nullptr;
  if (!odometry && (!o.refine.empty() || !o.perturb.empty())) {
    reg_summary = registrationJson(o, perturb, frames, reports, mapper.trajectoryError(truths));
  }
  nlohmann::json odometry_summary = nullptr;
  if (odometry) {
    double seconds = 0.0;
    for (const FrameReport& r : reports) seconds += r.seconds_register;
    odometry_summary = {{"frames", odometry_frames}, {"seconds", seconds}};
  }
  if (o.format == "json") {
    emit(nlohmann::json({{"frames", frames.size()},
                         {"poses", o.poses},
                         {"odometry", odometry_summary},
                         {"registration", reg_summary},
                         {"points_read", read},
                         {"points_kept", kept},
                         {"points_mapped", mapped},
                         {"global_points", global.size()},
                         {"seconds",
                          {{"load", load_s},
                           {"transform", transform_s},
                           {"map", map_s},
                           {"write", write_s},
                           {"total", secondsSince(t_start)}}},
                         {"map",
                          {{"plane", o.map_plane},
                           {"resolution", o.mapper.map_resolution},
                           {"width", image.width},
                           {"height", image.height},
                           {"origin", {image.origin_x, image.origin_y, 0.0}},
                           {"cells_with_hits", mapper.map().cells()},
                           {"occupied_cells", occupied},
                           {"min_hits", o.min_hits}}},
                         {"occupancy", occupancyJson(occupancy, reports)}})
                 .dump(2) +
             "\n",
         outputs);
    return;
  }
  Table tab({"frames", "points_read", "points_kept", "map_width", "map_height", "occupied_cells",
             "seconds"});
  tab.addRow({std::to_string(frames.size()), std::to_string(read), std::to_string(kept),
              std::to_string(image.width), std::to_string(image.height), std::to_string(occupied),
              fixed(secondsSince(t_start), 3)});
  emitTable(tab, o.format, outputs);
}

}  // namespace

void addKittiCommand(CLI::App& app) {
  auto o = std::make_shared<KittiOptions>();
  ScanMapperConfig& m = o->mapper;
  o->min_hits = m.min_hits;
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
  sub->add_option("--min-range", m.min_range, "Drop returns closer than this (m), e.g. the car")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--max-range", m.max_range, "Drop returns further than this (m)")
      ->check(kFinitePositive);
  sub->add_option("--min-height", m.min_height, "Map only points at or above this height (m)")
      ->check(kFinite);
  sub->add_option("--max-height", m.max_height, "Map only points at or below this height (m)")
      ->check(kFinite);
  sub->add_option("--voxel", m.voxel, "Per-scan and global voxel size (m), 0: off")
      ->check(kVoxelSize)
      ->capture_default_str();
  sub->add_option("--out-cloud", o->out_cloud, "Write the global cloud (.pcd)")->check(kOutputFile);
  addPcdFormatOption(*sub, o->pcd_format);
  sub->add_option("--out-map", o->out_map,
                  "map_server map: M.pgm + M.yaml, with M_preview.png and M_heat.png")
      ->check(kOutputFile);
  sub->add_option("--map-plane", o->map_plane, "Projection plane")
      ->check(CLI::IsMember({"xz", "xy", "yz"}))
      ->capture_default_str();
  sub->add_option("--map-resolution", m.map_resolution, "Map cell size (m), 0.0001 to 1000")
      ->check(kCellEdge)
      ->capture_default_str();
  sub->add_option("--min-hits", o->min_hits, "Hits that make a cell occupied")
      ->check(countIn(1, std::numeric_limits<std::uint32_t>::max()))
      ->capture_default_str();
  sub->add_option("--refine", o->refine,
                  "Align each scan to --refine-target (pcl::IterativeClosestPoint or "
                  "pcl::GeneralizedIterativeClosestPoint), starting from its pose")
      ->check(CLI::IsMember({"icp", "gicp"}));
  sub->add_option("--refine-target", o->refine_target,
                  "map: the refined scans so far; previous: the last scan; first: frame 0 only")
      ->check(CLI::IsMember({"map", "previous", "first"}))
      ->capture_default_str();
  sub->add_option("--target-voxel", m.registration.target_voxel,
                  "Cell of the accumulated registration target (m)")
      ->check(kFinitePositiveFloat)
      ->capture_default_str();
  sub->add_option("--out-poses", o->out_poses,
                  "Write the poses used (refined, perturbed or given), one 3x4 row-major line "
                  "per frame as in poses/NN.txt (velodyne poses with --world velodyne)")
      ->check(kOutputFile);
  sub->add_option("--perturb", o->perturb,
                  "t,r: move each pose after frame 0 by t metres and turn it by r degrees, "
                  "random directions (seeded)")
      ->check(CLI::Validator(
          [](std::string& s) {
            try {
              perturbation(s);
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
            return std::string();
          },
          "T,R"));
  sub->add_option("--seed", o->seed, "Random seed for --perturb")
      ->check(countIn(0, std::numeric_limits<unsigned>::max()))
      ->capture_default_str();
  sub->add_option("--poses", o->poses,
                  "file: poses/NN.txt; odometry: from the scans (LidarOdometry), no pose file "
                  "needed (--refine still applies on top)")
      ->check(CLI::IsMember({"file", "odometry"}))
      ->capture_default_str();
  sub->add_option("--occupancy-resolution", o->occupancy_resolution,
                  "Also build the 3D log-odds occupancy map (ray casting, OctoMap's model) with "
                  "voxels of this size (m), 0.0001 to 1000")
      ->check(kCellEdge);
  sub->add_option("--occupancy-max-range", o->occupancy_max_range,
                  "Beams longer than this are cut there and mark no hit (m)")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_option("--out-octomap", o->out_octomap, "Write the 3D map: .bt or .ot (OctoMap)")
      ->check(kOutputFile);
  sub->add_option("--out-trinary", o->out_trinary,
                  "Trinary map_server map (M.pgm + M.yaml) of the 3D map's --band (z, velodyne "
                  "world): occupied 0, free 254, unknown 205")
      ->check(kOutputFile);
  sub->add_option("--band", o->band, "zmin,zmax of --out-trinary (m)")
      ->check(CLI::Validator(
          [](std::string& s) {
            try {
              const std::vector<double> b = parseDoubleList(s, "--band");
              if (b.size() != 2 || b[0] > b[1]) return std::string("--band must be zmin,zmax");
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
            return std::string();
          },
          "ZMIN,ZMAX"));
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] { run(*o, *sub); });
}

}  // namespace metricmap::cli
