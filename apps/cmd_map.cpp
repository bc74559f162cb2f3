// metricmap map SOURCE --poses reference|odometry: a 2D hit map and a 2D log-odds occupancy grid
// (map_server PGM + YAML) and the global cloud of any scan source, built from the source's
// reference poses or from odometry.
#include <memory>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "map_report.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/output_set.h"
#include "metricmap/sequence/sequence_mapper.h"
#include "occupancy_2d_options.h"
#include "sequence_options.h"

namespace metricmap::cli {
namespace {

struct MapOptions {
  SourceOptions source;
  RangeOptions ranges;  // the odometry's (with --poses odometry)
  std::string poses = "reference", profile, out_map, out_cloud, pcd_format = "binary";
  std::string format = "table";
  double resolution = 0.1, voxel = 0.0;
  std::optional<double> min_height, max_height;
  unsigned min_hits = 1;
  Occupancy2DOptions grid;
  std::string world = "first-scan";
};

void run(const MapOptions& o) {
  const auto t_start = std::chrono::steady_clock::now();
  std::unique_ptr<ScanSource> source = openSource(o.source);
  const std::vector<std::size_t> frames = selectedFrames(o.source, *source);
  std::vector<Eigen::Isometry3d> poses;
  if (o.poses == "odometry") {
    OdometryRunOptions ro;
    ro.frames = frames;
    ro.world = parseWorldFrame(o.world);
    applyRangeOptions(o.ranges, o.profile, source->info(), ro.config, ro.profile);
    poses = odometrySensorPoses(runOdometryNamed(*source, ro), source->info());
  } else {
    poses = referenceSensorPoses(*source, frames);
  }
  ScanMapperConfig c;
  const MapConvention convention = mapConvention(source->info());
  c.up = convention.up;
  c.plane = convention.plane;
  c.map_resolution = o.resolution;
  c.min_hits = o.min_hits;
  c.voxel = o.voxel;
  c.keep_global_cloud = !o.out_cloud.empty();
  if (o.min_height) c.min_height = *o.min_height;
  if (o.max_height) c.max_height = *o.max_height;
  c.occupancy_2d = occupancy2DConfig(o.grid);
  SequenceMapper builder(*source, c);
  const ScanMapper& maps = builder.build(poses, frames);

  const MapImage image = maps.map().image();
  if (!o.out_map.empty() && image.width == 0) {
    throw InputError("the map is empty: no point fell within the height band");
  }
  requireOccupiedCells(image, c.min_hits, o.out_map);
  OutputSet outputs;  // committed once the report is printed
  if (!o.out_map.empty()) {
    MapServerFiles files = mapServerFiles(o.out_map);
    for (std::string* path : {&files.pgm, &files.yaml, &files.preview_png, &files.heat_png}) {
      *path = outputs.stage(*path);
    }
    writeMapServer(mapServerImage(image, c.min_hits), files, heatImage(image));
  }
  if (!o.out_cloud.empty()) {
    savePcdAtomic(outputs.stage(o.out_cloud), maps.globalCloud(), parsePcdFormat(o.pcd_format));
  }
  const nlohmann::json grid = writeOccupancy2D(maps, o.grid, outputs);
  const MapReportFigures figures{source->info().path,  o.poses, frames.size(),    c.map_resolution,
                                 maps.occupiedCells(), grid,    o.grid.resolution};
  emit(mapReport(o.format, image, figures, t_start), outputs);
}

}  // namespace

void addMapCommand(CLI::App& app) {
  auto o = std::make_shared<MapOptions>();
  CLI::App* sub = app.add_subcommand(
      "map", "Any scan source + reference poses or odometry -> 2D hit map and global cloud");
  addSourceOptions(*sub, o->source);
  sub->add_option("--poses", o->poses,
                  "reference (the source's pose file, or --reference) or odometry (from the "
                  "scans: the odometry command's options below)")
      ->check(CLI::IsMember({"reference", "odometry"}))
      ->capture_default_str();
  addRangeOptions(*sub, o->ranges, o->profile);
  sub->add_option("--world-frame", o->world,
                  "With --poses odometry: the map's world, level (z up along the first scan's "
                  "ground normal) or first-scan (the first scan's sensor frame)")
      ->check(CLI::IsMember({"level", "first-scan"}))
      ->capture_default_str();
  sub->add_option("--out-map", o->out_map,
                  "map_server map: M.pgm, M.yaml, M_preview.png, M_heat.png (black: at least "
                  "--min-hits points in the cell)")
      ->check(kOutputFile);
  sub->add_option("--out-cloud", o->out_cloud, "The registered scans as one PCD")
      ->check(kOutputFile);
  addPcdFormatOption(*sub, o->pcd_format);
  sub->add_option("--map-resolution", o->resolution, "Map cell (m)")
      ->check(kCellEdge)
      ->capture_default_str();
  sub->add_option("--min-hits", o->min_hits, "Points that make a cell occupied")
      ->check(countIn(1, 1000000))
      ->capture_default_str();
  sub->add_option("--min-height", o->min_height, "Lowest point mapped, along up (m)")
      ->check(kFinite);
  sub->add_option("--max-height", o->max_height, "Highest point mapped (m)")->check(kFinite);
  sub->add_option("--voxel", o->voxel, "Average the global cloud in cells of this size (m)")
      ->check(finiteIn(0, 1000));
  addOccupancy2DOptions(*sub, o->grid);
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    if (o->poses != "odometry" && (o->ranges.max_range || o->ranges.min_range ||
                                   o->ranges.voxel_size || !o->profile.empty())) {
      throw CLI::ValidationError("--max-range/--min-range/--voxel-size/--profile",
                                 "set the odometry: give them with --poses odometry");
    }
    if (o->min_height && o->max_height && !(*o->min_height < *o->max_height)) {
      throw CLI::ValidationError("--min-height", "must be below --max-height");
    }
    if (o->out_map.empty() && o->out_cloud.empty() && o->grid.out.empty()) {
      throw CLI::ValidationError("--out-map",
                                 "give --out-map, --out-occupancy-2d and/or --out-cloud");
    }
    checkOccupancy2DOptions(*sub, o->grid);
    refuseIgnored(*sub, "--world-frame", o->poses == "odometry", "without --poses odometry");
    refuseIgnored(*sub, "--pcd-format", !o->out_cloud.empty(), "without --out-cloud");
    checkRangeOptions(*sub, o->ranges);
    checkSourceOptions(*sub, o->source);
    RolePaths outputs = {{"--out-cloud", o->out_cloud}};
    if (!o->out_map.empty()) {
      const MapServerFiles f = mapServerFiles(o->out_map);
      outputs.insert(outputs.end(), {{"--out-map", f.pgm},
                                     {"--out-map (its .yaml)", f.yaml},
                                     {"--out-map (its preview)", f.preview_png},
                                     {"--out-map (its heat map)", f.heat_png}});
    }
    for (const auto& role : occupancy2DOutputs(o->grid)) outputs.push_back(role);
    requireDistinctFiles(sourceInputs(o->source), outputs);
    requireExtension("--out-map", o->out_map, {".pgm"}, "a map_server PGM with its YAML");
    requireExtension("--out-cloud", o->out_cloud, {".pcd"}, "a PCD cloud");
    run(*o);
  });
}

}  // namespace metricmap::cli
