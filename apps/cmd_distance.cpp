// metricmap distance MAP: the exact Euclidean distance field of a map (.bt/.ot log-odds map,
// map_server YAML, point cloud map), written as .npy, queried at points, and for 2D maps an
// inflation costmap.
#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "distance_query_csv.h"
#include "metricmap/distance/distance_sources.h"
#include "metricmap/distance/distance_volume.h"
#include "metricmap/distance/inflation_costmap.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/array_writers.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/map_server_reader.h"
#include "metricmap/io/point_rows_csv.h"
#include "metricmap/occupancy/octomap_quiet.h"
#include "table.h"

namespace metricmap::cli {
namespace {

struct DistanceOptions {
  std::string map;
  double max_distance = 2.0;
  double resolution = 0.0;
  std::string unknown = "free";
  bool signed_distance = false;
  std::string out, out_vdb, out_costmap, query, out_query, format = "table";
  unsigned threads = 0;
  InflationParams inflation;
};

enum class MapKind { LogOdds, MapServer, Points };

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

MapKind kindOf(const std::string& path) {
  const std::string p = lower(path);
  const auto ends = [&](const char* e) {
    const std::string s(e);
    return p.size() >= s.size() && p.compare(p.size() - s.size(), s.size(), s) == 0;
  };
  if (ends(".bt") || ends(".ot")) return MapKind::LogOdds;
  if (ends(".yaml") || ends(".yml")) return MapKind::MapServer;
  return MapKind::Points;
}

const char* kindName(MapKind k) {
  return k == MapKind::LogOdds ? "log-odds" : (k == MapKind::MapServer ? "map_server" : "points");
}

std::string joined(const Eigen::Vector3d& v, int dims) {
  std::ostringstream s;
  for (int a = 0; a < dims; ++a) s << (a ? " " : "") << v[a];
  return s.str();
}

void runDistance(const CLI::App& app, const DistanceOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const MapKind kind = kindOf(o.map);
  refuseIgnored(app, "--resolution", kind == MapKind::Points,
                "for a log-odds or map_server map (their resolution is their own)");
  if (kind == MapKind::Points && o.resolution <= 0.0)
    throw UsageError("distance: a point map needs --resolution");
  const bool costmap = !o.out_costmap.empty();
  if (costmap && kind != MapKind::MapServer)
    throw UsageError("--out-costmap needs a 2D map (a map_server YAML)");
  for (const char* opt : {"--inscribed-radius", "--inflation-radius", "--cost-scaling-factor"})
    refuseIgnored(app, opt, costmap, "without --out-costmap");
  // nav2's inflation reads the unsigned distance with unknown cells as free: a costmap of a
  // signed field, or of unknown space as obstacles, is not one nav2 would make.
  if (costmap && (o.signed_distance || o.unknown == "occupied"))
    throw UsageError(std::string("--out-costmap is made from the unsigned field with unknown "
                                 "space as free: drop ") +
                     (o.signed_distance ? "--signed" : "--unknown occupied") +
                     " or compute the costmap in a run of its own");
  if (o.query.empty() != o.out_query.empty())
    throw UsageError("--query and --out-query go together");
  requireExtension("--out", o.out, {".npy"}, "NumPy");
  requireExtension("--out-vdb", o.out_vdb, {".vdb"}, "OpenVDB");
  requireExtension("--out-costmap", o.out_costmap, {".pgm"}, "PGM");
  MapServerFiles cost_files;
  RolePaths outputs = {{"--out", o.out}, {"--out-vdb", o.out_vdb}, {"--out-query", o.out_query}};
  if (costmap) {
    cost_files = mapServerFiles(o.out_costmap);
    cost_files.preview_png.clear();
    cost_files.heat_png.clear();
    outputs.push_back({"--out-costmap", cost_files.pgm});
    outputs.push_back({"--out-costmap (YAML)", cost_files.yaml});
  }
  RolePaths inputs = {{"map", o.map}, {"--query", o.query}};
  if (kind == MapKind::MapServer)
    inputs.push_back({"map's image", readMapServerYaml(o.map).image_path});
  requireDistinctFiles(inputs, outputs);

  DistanceFieldParams params;
  params.max_distance = o.max_distance;
  params.unknown = o.unknown == "occupied" ? UnknownAs::Occupied : UnknownAs::Free;
  params.signed_distance = o.signed_distance;
  params.threads = o.threads;
  std::vector<double> points;
  if (!o.query.empty()) points = readPointRows(o.query);

  OccupancyBox box;
  std::unique_ptr<Map2D> map2d;
  if (kind == MapKind::LogOdds) {
    box = occupancyBoxOf(readOctomapQuietly(o.map), params);
  } else if (kind == MapKind::MapServer) {
    map2d = std::make_unique<Map2D>(loadMapServer(o.map));
    box = occupancyBoxOf(*map2d, params);
  } else {
    const LoadedCloud loaded = loadTimed(o.map);
    try {
      box = occupancyBoxOf(*loaded.cloud, o.resolution, params);
    } catch (const CapacityError& e) {
      throw CapacityError(o.map + ": " + e.what());
    }
  }
  const double load_seconds = secondsSince(start);
  const DistanceField field(std::move(box), params);
  const std::size_t occupied = field.occupiedVoxels(), obstacles = field.obstacleVoxels();
  if (obstacles == 0) {
    std::cerr << "warning: " << o.map << " has no occupied voxel: every distance is the max ("
              << o.max_distance << " m)\n";
  }

  OutputSet staged;
  const int dims = field.dimensions();
  if (!o.out.empty()) {
    std::vector<std::size_t> shape(field.shape().begin(), field.shape().begin() + dims);
    writeNpyFloat32(staged.stage(o.out), shape, field.field());
  }
  if (!o.out_vdb.empty()) writeVdb(staged.stage(o.out_vdb), vdbVolumeOf(field));
  std::size_t lethal = 0;
  if (costmap) {
    DistanceFieldParams cp;
    cp.max_distance = inflationReach(field.resolution(), o.inflation);
    cp.threads = o.threads;
    const DistanceField cf(occupancyBoxOf(*map2d, cp), cp);
    const MapServerImage cost = inflationCostmap(cf, o.inflation);
    for (std::uint8_t c : cost.pixels) lethal += c == kCostLethal;
    writeMapServer(cost, cost_files, staged);
  }
  if (!o.query.empty()) writeTextAtomic(staged.stage(o.out_query), queryCsv(field, points));

  nlohmann::json j;
  j["map"] = o.map;
  j["kind"] = kindName(kind);
  j["dimensions"] = dims;
  j["origin"] = std::vector<double>(field.origin().data(), field.origin().data() + dims);
  j["resolution"] = field.resolution();
  j["shape"] = std::vector<std::size_t>(field.shape().begin(), field.shape().begin() + dims);
  j["max_distance"] = o.max_distance;
  j["signed"] = o.signed_distance;
  j["unknown"] = o.unknown;
  j["counts"] = {{"voxels", field.voxels()},         {"occupied", occupied},
                 {"obstacles", obstacles},           {"unknown", field.unknownVoxels()},
                 {"clamped", field.clampedVoxels()}, {"queries", points.size() / 3}};
  if (costmap) j["counts"]["lethal_cells"] = lethal;
  j["no_obstacle"] = obstacles == 0;
  j["seconds"] = {
      {"load", load_seconds}, {"field", field.seconds()}, {"total", secondsSince(start)}};
  j["memory"] = {{"field_bytes", field.bytes()}};
  std::string text;
  if (o.format == "json") {
    text = j.dump(2) + "\n";
  } else {
    Table t({"quantity", "value"});
    t.addRow({"map", o.map + " (" + kindName(kind) + ")"});
    t.addRow({"origin (m)", joined(field.origin(), dims)});
    t.addRow({"resolution (m)", plainNumber(field.resolution())});
    std::string shape;
    for (int a = 0; a < dims; ++a) shape += (a ? " x " : "") + std::to_string(field.shape()[a]);
    t.addRow({"shape", shape});
    t.addRow({"max distance (m)", plainNumber(o.max_distance)});
    t.addRow({"occupied", std::to_string(occupied)});
    t.addRow({"obstacles",
              std::to_string(obstacles) + (obstacles == 0 ? " (every distance = max)" : "")});
    t.addRow({"unknown", std::to_string(field.unknownVoxels())});
    t.addRow({"clamped", std::to_string(field.clampedVoxels())});
    t.addRow({"field (s)", fixed(field.seconds(), 3)});
    t.addRow({"total (s)", fixed(secondsSince(start), 3)});
    text = renderTable(t, o.format);
  }
  emit(text, staged);
}

}  // namespace

void addDistanceCommand(CLI::App& app) {
  auto o = std::make_shared<DistanceOptions>();
  CLI::App* sub = app.add_subcommand(
      "distance", "Exact Euclidean distance field of a map (.bt/.ot, map_server YAML, cloud)");
  sub->add_option("map", o->map, "Map: OctoMap .bt/.ot, map_server .yaml, or a point cloud map")
      ->required();
  sub->add_option("--max-distance", o->max_distance, "Distances are clamped here (m)")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_option("--resolution", o->resolution, "Voxel edge for a point map (m)")
      ->check(kCellEdge);
  sub->add_option("--unknown", o->unknown, "Unknown space counts as free or occupied")
      ->check(CLI::IsMember({"free", "occupied"}))
      ->capture_default_str();
  sub->add_flag("--signed", o->signed_distance, "Negative inside obstacles");
  sub->add_option("--out", o->out, "The field as .npy (float32, metres, C order)")
      ->check(kOutputFile);
  sub->add_option("--out-vdb", o->out_vdb,
                  "The field as OpenVDB (FloatGrid \"distance\", voxels at the max inactive)")
      ->check(kOutputFile);
  sub->add_option("--out-costmap", o->out_costmap,
                  "2D maps: nav2 inflation costmap as map_server PGM + YAML (raw mode)")
      ->check(kOutputFile);
  sub->add_option("--inscribed-radius", o->inflation.inscribed_radius, "Costmap: robot radius (m)")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--inflation-radius", o->inflation.inflation_radius,
                  "Costmap: inflation radius (m)")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--cost-scaling-factor", o->inflation.cost_scaling_factor,
                  "Costmap: exponential decay (1/m)")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--query", o->query, "CSV of points x,y[,z] to query")->check(kOutputFile);
  sub->add_option("--out-query", o->out_query, "CSV of x,y,z,distance,gx,gy,gz,inside")
      ->check(kOutputFile);
  sub->add_option("--threads", o->threads, "Threads (0: all)")->check(countIn(0, 1024));
  addFormatOption(*sub, o->format, {"table", "csv", "json"});
  sub->callback([sub, o] { runDistance(*sub, *o); });
}

}  // namespace metricmap::cli
