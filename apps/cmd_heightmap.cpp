// metricmap heightmap DEPTH...: height-binned top-down map (obstacles, explored, layers, counts).
#include <cmath>
#include <limits>
#include <memory>

#include "camera_options.h"
#include "camera_pose_options.h"
#include "cli_common.h"
#include "commands.h"
#include "heightmap_report.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/array_writers.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/output_set.h"
#include "metricmap/mapping/height_map.h"
#include "metricmap/mapping/height_map_builder.h"
#include "metricmap/mapping/height_map_images.h"

namespace metricmap::cli {
namespace {

struct HeightMapOptions {
  std::vector<std::string> depths;
  CameraOptions camera;
  CameraPoseOptions pose;
  std::string out_prefix, format = "json";
  double resolution = HeightMapParams{}.resolution;
  long long map_size = static_cast<long long>(HeightMapParams{}.map_size);
  long long obstacle_threshold = HeightMapParams{}.obstacle_threshold;
  std::string z_bins;
};

void run(const HeightMapOptions& o, const CLI::App& app) {
  checkCameraPoseOptions(app, o.pose);
  {
    RolePaths inputs = withRole("depth image", o.depths);
    requireDistinctInputs(inputs);
    inputs.emplace_back("--camera file", o.camera.camera_file);
    inputs.emplace_back("--trajectory file", o.pose.trajectory);
    RolePaths outputs;
    for (const char* suffix : {"_obstacles.png", "_explored.png", "_layers.png", "_counts.npy"})
      outputs.emplace_back(std::string("--out-prefix (its ") + suffix + ")", o.out_prefix + suffix);
    requireDistinctFiles(inputs, outputs);
  }
  HeightMapParams params;
  params.resolution = o.resolution;
  params.map_size = static_cast<std::size_t>(o.map_size);
  params.z_bins = parseNumbersOption(o.z_bins, "--z-bins");
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

  HeightMapBuilder builder(map, resolveCameraPoses(o.pose, o.depths.size()));
  for (const std::string& path : o.depths) {
    const DepthImage depth = readDepthImage(path);
    const CameraIntrinsics k = resolveIntrinsics(o.camera, depth);
    builder.addFrame(depthToCloud(depth, k, resolveDepthScale(o.camera, k, depth)));
  }
  OutputSet outputs;  // committed once the report is printed
  const HeightMapImages images = heightMapImages(map);
  const int n = static_cast<int>(map.size());
  writePng(outputs.stage(o.out_prefix + "_obstacles.png"), n, n, 1, images.obstacles);
  writePng(outputs.stage(o.out_prefix + "_explored.png"), n, n, 1, images.explored);
  writePng(outputs.stage(o.out_prefix + "_layers.png"), n, n, 3, images.layers);
  writeNpyUint32(outputs.stage(o.out_prefix + "_counts.npy"), {map.size(), map.size(), map.bins()},
                 map.counts());
  emitHeightMapReport(map, builder.floors(), builder.seconds(), o.format, outputs);
}

}  // namespace

void addHeightMapCommand(CLI::App& app) {
  auto o = std::make_shared<HeightMapOptions>();
  CLI::App* sub = app.add_subcommand("heightmap", "Height-binned top-down map from depth images");
  sub->add_option("depth", o->depths, "16-bit depth images; every frame adds to the map")
      ->required();
  addCameraOptions(*sub, o->camera);
  addCameraPoseOptions(*sub, o->pose);
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
