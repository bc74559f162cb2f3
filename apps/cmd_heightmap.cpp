// metricmap heightmap DEPTH...: height-binned top-down map (obstacles, explored, layers, counts).
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "camera_options.h"
#include "cli_common.h"
#include "commands.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/array_writers.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/output_set.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/mapping/floor_fit.h"
#include "metricmap/mapping/height_map.h"
#include "table.h"

namespace metricmap::cli {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct HeightMapOptions {
  std::vector<std::string> depths;
  CameraOptions camera;
  double camera_height = NAN, pitch_deg = 0.0, yaw_deg = 0.0;
  std::string pose_matrix, trajectory, out_prefix, format = "json";
  bool auto_floor = false;
  double resolution = HeightMapParams{}.resolution, floor_distance = 0.02;
  long long map_size = static_cast<long long>(HeightMapParams{}.map_size);
  long long obstacle_threshold = HeightMapParams{}.obstacle_threshold;
  std::string z_bins;
};

/// A list option through the checked parser; a refused list is a usage error (exit 2).
std::vector<double> parseNumbers(const std::string& text, const std::string& what) {
  try {
    return parseDoubleList(text, what);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(what, e.what());
  }
}

Eigen::Isometry3d poseFromMatrix(const std::string& text) {
  const std::vector<double> m = parseNumbers(text, "--pose-matrix");
  if (m.size() != 16)
    throw CLI::ValidationError("--pose-matrix", "needs 16 numbers (row-major 4x4)");
  Eigen::Matrix4d t;
  for (int i = 0; i < 16; ++i) t(i / 4, i % 4) = m[static_cast<std::size_t>(i)];
  try {
    checkRigidTransform(t, "--pose-matrix");  // a zero matrix would collapse every point
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  Eigen::Isometry3d pose;
  pose.matrix() = t;
  return pose;
}

std::vector<std::uint8_t> layerColour(std::size_t bin, std::size_t bins) {
  // Low bins blue, middle (obstacles) red, high bins green-yellow.
  static const std::uint8_t palette[][3] = {{70, 110, 220}, {220, 50, 40},  {240, 200, 40},
                                            {60, 180, 90},  {160, 90, 200}, {90, 200, 220}};
  const std::uint8_t* c = palette[bin % 6];
  (void)bins;
  return {c[0], c[1], c[2]};
}

void writeImages(const HeightMap& map, const std::string& prefix, OutputSet& outputs) {
  const int n = static_cast<int>(map.size());
  std::vector<std::uint8_t> obstacles(static_cast<std::size_t>(n) * n), explored(obstacles.size()),
      layers(obstacles.size() * 3, 0);
  for (std::size_t r = 0; r < map.size(); ++r) {
    for (std::size_t c = 0; c < map.size(); ++c) {
      const std::size_t i = r * map.size() + c;
      obstacles[i] = map.obstacle(r, c) ? 0 : 255;
      explored[i] = map.explored(r, c) ? 255 : 0;
      std::size_t best = 0;
      std::uint32_t most = 0;
      for (std::size_t b = 0; b < map.bins(); ++b) {
        if (map.count(r, c, b) > most) {
          most = map.count(r, c, b);
          best = b;
        }
      }
      if (most > 0) {
        const auto rgb = layerColour(best, map.bins());
        std::copy(rgb.begin(), rgb.end(), layers.begin() + static_cast<std::ptrdiff_t>(3 * i));
      }
    }
  }
  writePng(outputs.stage(prefix + "_obstacles.png"), n, n, 1, obstacles);
  writePng(outputs.stage(prefix + "_explored.png"), n, n, 1, explored);
  writePng(outputs.stage(prefix + "_layers.png"), n, n, 3, layers);
  writeNpyUint32(outputs.stage(prefix + "_counts.npy"), {map.size(), map.size(), map.bins()},
                 map.counts());
}

/// A TUM trajectory gives frame k the k-th pose line, so it holds exactly one pose line per
/// depth image: readTumTrajectory checked the first `frames`; a line beyond them (extra poses
/// would mean the images are not the trajectory's first frames, or not in its order) is an
/// error naming the file and that line. Blank lines and '#' comments are not pose lines. The
/// file is scanned in blocks (a line may be as long as the file).
void requireNoExtraPoses(const std::string& path, std::size_t frames) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  std::vector<char> block(1 << 16);
  std::size_t line = 1, poses = 0, column = 0;
  bool comment = false, content = false;
  const auto endLine = [&] {
    if (content && ++poses > frames) {
      throw InputError(path + ": line " + std::to_string(line) + " is a pose line beyond the " +
                       std::to_string(frames) +
                       " depth image(s) given: frame k takes the k-th pose line, so the "
                       "trajectory must hold one line per image, in order");
    }
    ++line;
    column = 0;
    comment = content = false;
  };
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got; ++i) {
      const char c = block[static_cast<std::size_t>(i)];
      if (c == '\n') {
        endLine();
        continue;
      }
      if (column++ == 0 && c == '#') comment = true;
      if (!comment && c != ' ' && c != '\t' && c != '\r') content = true;
    }
  }
  endLine();  // a last line without a newline
}

void run(const HeightMapOptions& o, const CLI::App& app) {
  const int sources = (!std::isnan(o.camera_height) ? 1 : 0) + (!o.pose_matrix.empty() ? 1 : 0) +
                      (!o.trajectory.empty() ? 1 : 0) + (o.auto_floor ? 1 : 0);
  if (sources != 1) {
    throw CLI::ValidationError("pose",
                               "give exactly one of --camera-height (with --pitch-deg, "
                               "--yaw-deg), --pose-matrix, --trajectory, --auto-floor");
  }
  // --pitch-deg and --yaw-deg turn the camera of --camera-height; any other pose ignores them.
  for (const char* option : {"--pitch-deg", "--yaw-deg"}) {
    refuseIgnored(app, option, !std::isnan(o.camera_height),
                  "without --camera-height: the pose comes from --pose-matrix, --trajectory or "
                  "--auto-floor");
  }
  {
    RolePaths inputs = withRole("depth image", o.depths);
    requireDistinctInputs(inputs);
    inputs.emplace_back("--camera file", o.camera.camera_file);
    inputs.emplace_back("--trajectory file", o.trajectory);
    RolePaths outputs;
    for (const char* suffix : {"_obstacles.png", "_explored.png", "_layers.png", "_counts.npy"})
      outputs.emplace_back(std::string("--out-prefix (its ") + suffix + ")", o.out_prefix + suffix);
    requireDistinctFiles(inputs, outputs);
  }
  HeightMapParams params;
  params.resolution = o.resolution;
  params.map_size = static_cast<std::size_t>(o.map_size);
  params.z_bins = parseNumbers(o.z_bins, "--z-bins");
  for (std::size_t i = 1; i < params.z_bins.size(); ++i) {
    if (!(params.z_bins[i] > params.z_bins[i - 1])) {  // quoted as given: `1e1,1e0`
      throw UsageError("--z-bins: '" + quoteForMessage(o.z_bins) + "' must be strictly increasing");
    }
  }
  const auto cells =
      static_cast<std::uint64_t>(o.map_size) * static_cast<std::uint64_t>(o.map_size);
  // counts (4 bytes a bin) twice (the map and the .npy), five image bytes a cell twice (ours,
  // VTK's)
  checkMemory(cells, 8 * (params.z_bins.size() + 1) + 10,
              "--map-size " + std::to_string(o.map_size) + " with " +
                  std::to_string(params.z_bins.size() + 1) + " height bins");
  params.obstacle_threshold = static_cast<std::uint32_t>(o.obstacle_threshold);
  // The map checks sizes and bins before any file is read; a bad option is a usage error.
  std::unique_ptr<HeightMap> map_holder;
  try {
    map_holder = std::make_unique<HeightMap>(params);
  } catch (const CapacityError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--z-bins/--resolution/--map-size", e.what());
  }
  HeightMap& map = *map_holder;

  const Eigen::Isometry3d given_pose =
      o.pose_matrix.empty() ? Eigen::Isometry3d::Identity() : poseFromMatrix(o.pose_matrix);
  std::vector<Eigen::Isometry3d> trajectory;
  if (!o.trajectory.empty()) {
    trajectory = readTumTrajectory(o.trajectory, o.depths.size());
    requireNoExtraPoses(o.trajectory, o.depths.size());
  }
  nlohmann::json floors = nlohmann::json::array();
  double seconds = 0.0;
  for (std::size_t f = 0; f < o.depths.size(); ++f) {
    const DepthImage depth = readDepthImage(o.depths[f]);
    const CameraIntrinsics k = resolveIntrinsics(o.camera, depth);
    const auto cloud = depthToCloud(depth, k, resolveDepthScale(o.camera, k, depth));
    Eigen::Isometry3d pose;
    if (o.auto_floor) {
      const FloorPlane floor = fitFloor(cloud, o.floor_distance);
      pose = cameraToMapFromFloor(floor.normal, floor.d);
      floors.push_back({{"frame", f},
                        {"plane", {floor.normal.x(), floor.normal.y(), floor.normal.z(), floor.d}},
                        {"camera_height", floor.cameraHeight()},
                        {"inliers", floor.inliers}});
    } else if (!trajectory.empty()) {
      pose = trajectory[f];
    } else if (!o.pose_matrix.empty()) {
      pose = given_pose;
    } else {
      pose = cameraToMap(o.camera_height, o.pitch_deg * kDeg, o.yaw_deg * kDeg);
    }
    const auto t0 = std::chrono::steady_clock::now();
    map.addFrame(cloud, pose);
    seconds += secondsSince(t0);
  }
  OutputSet outputs;  // committed once the report is printed
  writeImages(map, o.out_prefix, outputs);

  const HeightMapStatistics& s = map.statistics();
  nlohmann::json j = {{"frames", s.frames},
                      {"map_size", map.size()},
                      {"resolution", params.resolution},
                      {"z_bins", params.z_bins},
                      {"bin_counts", s.bin_counts},
                      {"points_outside_map", s.points_outside_map},
                      {"points", s.valid_points},  // finite points binned or outside
                      {"obstacle_cells", map.obstacleCells()},
                      {"explored_cells", map.exploredCells()},
                      {"floor", floors.empty() ? nlohmann::json(nullptr) : floors.front()},
                      {"seconds", seconds}};
  if (floors.size() > 1) j["floors"] = floors;
  if (o.format == "json") {
    emit(j.dump(2) + "\n", outputs);
    return;
  }
  Table t({"frames", "points", "outside_map", "obstacle_cells", "explored_cells", "bin_counts"});
  std::string bins;
  for (auto b : s.bin_counts) bins += (bins.empty() ? "" : " ") + std::to_string(b);
  t.addRow({std::to_string(s.frames), std::to_string(s.valid_points),
            std::to_string(s.points_outside_map), std::to_string(map.obstacleCells()),
            std::to_string(map.exploredCells()), bins});
  emitTable(t, o.format, outputs);
}

}  // namespace

void addHeightMapCommand(CLI::App& app) {
  auto o = std::make_shared<HeightMapOptions>();
  CLI::App* sub = app.add_subcommand("heightmap", "Height-binned top-down map from depth images");
  sub->add_option("depth", o->depths, "16-bit depth images; every frame adds to the map")
      ->required();
  addCameraOptions(*sub, o->camera);
  sub->add_option("--camera-height", o->camera_height, "Camera height above the floor, metres")
      ->check(kFiniteNonNegative);
  sub->add_option("--pitch-deg", o->pitch_deg, "Camera pitch, degrees (positive: looking down)")
      ->check(finiteIn(-90.0, 90.0));
  sub->add_option("--yaw-deg", o->yaw_deg, "Camera yaw, degrees")->check(finiteIn(-360.0, 360.0));
  sub->add_option("--pose-matrix", o->pose_matrix, "Camera-to-map 4x4, 16 numbers row-major");
  sub->add_option("--trajectory", o->trajectory,
                  "TUM trajectory (timestamp tx ty tz qx qy qz qw), one line per depth image, "
                  "in order (more lines than images: an error)");
  sub->add_flag("--auto-floor", o->auto_floor,
                "Fit the floor (RANSAC plane, PCL sample_consensus) and measure heights from it");
  sub->add_option("--resolution", o->resolution, "Cell edge, metres")
      ->required()
      ->check(kFinitePositive);
  sub->add_option("--map-size", o->map_size, "Cells per side")
      ->required()
      ->check(countIn(1, 0xFFFFFFFFull));  // side^2 cells must be countable in 64 bits
  sub->add_option("--z-bins", o->z_bins, "Height bin edges a,b[,...] (strictly increasing)")
      ->required();
  sub->add_option("--obstacle-threshold", o->obstacle_threshold,
                  "Middle-bin count that marks an obstacle")
      ->check(countIn(0, std::numeric_limits<std::uint32_t>::max()))
      ->capture_default_str();
  sub->add_option("--out-prefix", o->out_prefix,
                  "Writes PREFIX_obstacles.png, _explored.png, _layers.png, _counts.npy")
      ->required()
      ->check(kOutputFile);
  addFormatOption(*sub, o->format, {"json", "table"});
  sub->callback([o, sub] { run(*o, *sub); });
}

}  // namespace metricmap::cli
