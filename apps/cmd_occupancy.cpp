// metricmap occupancy INPUT...: KITTI scans or PCD files (VIEWPOINT = sensor pose) cast into a
// probabilistic voxel map (LogOddsMap), written as OctoMap .bt/.ot, occupied voxel centres and
// a trinary map_server map from a height band. A .bt/.ot INPUT is read and exported instead.
// With --distributed (under mpirun) each rank casts its contiguous share of the frames or files
// and the voxels are merged over MPI (ranks.h); rank 0 writes the outputs.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include <pcl/common/transforms.h>
#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/bag_reader.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/output_set.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "metricmap/occupancy/octomap_io.h"
#include "metricmap/occupancy/scan_casting.h"
#include "metricmap/sequence/sequence_mapper.h"
#include "octomap_quiet.h"
#include "ranks.h"
#include "sequence_options.h"
#include "table.h"

namespace metricmap::cli {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

struct OccupancyOptions {
  std::vector<std::string> inputs;
  std::string sequence = "00", frames, world = "velodyne";
  std::string out_bt, out_ot, out_cloud, out_map, map_preview, band, format = "table";
  std::string pcd_format = "binary", topic, reference;
  double resolution = kUnset, max_range = kUnset;
  unsigned threads = 1;
  bool threads_given = false;
  bool resolution_given = false, max_range_given = false, distributed = false;
  bool sequence_given = false, world_given = false, pcd_format_given = false;
};

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool isDirectory(const std::string& path) {
  return access((path + "/sequences").c_str(), F_OK) == 0;
}

/// A scan source other than a KITTI root: a folder of scans (with poses.txt), a .txt list, a
/// CARMEN log, a ROS bag. Its scans are cast at the source's reference poses (--reference).
bool isScanSource(const std::vector<std::string>& inputs) {
  if (inputs.size() != 1 || isDirectory(inputs[0])) return false;
  std::error_code ec;
  const std::string& p = inputs[0];
  return std::filesystem::is_directory(p, ec) || endsWith(p, ".txt") || endsWith(p, ".clf") ||
         endsWith(p, ".log") || endsWith(p, ".gz") || endsWith(p, ".bz2") || looksLikeBag(p);
}

/// "zmin,zmax" -> two finite numbers, zmin <= zmax (the checked parser: no hex, inf, nan).
std::pair<double, double> parseBand(const std::string& text) {
  try {
    const std::vector<double> v = parseDoubleList(text, "--band");
    if (v.size() != 2 || v[0] > v[1]) throw std::invalid_argument("");
    return {v[0], v[1]};
  } catch (const std::invalid_argument&) {
    throw UsageError("--band must be zmin,zmax (finite decimal numbers, zmin <= zmax), got '" +
                     quoteForMessage(text) + "'");
  }
}

/// The YAML of --out-map's map_server pair: M.pgm -> M.yaml.
std::string yamlOf(const std::string& pgm) { return mapServerFiles(pgm).yaml; }

/// What the exports of a .bt/.ot input build per expanded voxel, checked with the map against
/// the budget before the tree is expanded (a 30-byte tree can stand for 2^27 voxels).
OctomapUse exportUse(const OccupancyOptions& o) {
  // OctoMap tree before pruning: a 16-byte leaf node (+ allocator overhead), its share of the
  // parents' nodes and child arrays
  constexpr std::uint64_t kOctomapNodeBytes = 48;
  // a cloud point (16 bytes), the voxel centre (24) and the PCD writer's copy
  constexpr std::uint64_t kCloudPointBytes = 64;
  OctomapUse use;
  std::string purpose;
  for (const auto& [option, path] :
       {std::pair<std::string, std::string>{"--out", o.out_bt}, {"--out-ot", o.out_ot}}) {
    if (path.empty()) continue;
    use.bytes_per_occupied_voxel = use.bytes_per_free_voxel = kOctomapNodeBytes;
    purpose += (purpose.empty() ? "" : " and ") + option;
  }
  if (!o.out_cloud.empty()) {
    use.bytes_per_occupied_voxel += kCloudPointBytes;
    purpose += (purpose.empty() ? "" : " and ") + std::string("--out-cloud");
  }
  if (!purpose.empty()) use.purpose = "exported as " + purpose;
  return use;
}

struct Totals : ScanCastTotals {
  double write_s = 0;
  double insert_cpu_s = -1;  ///< distributed: insert seconds summed over the ranks
};

void castScans(const OccupancyOptions& o, const Ranks& ranks, LogOddsMap& map, Totals& tot) {
  const bool progress = isatty(STDERR_FILENO) != 0 && !ranks.distributed();
  const auto t_start = std::chrono::steady_clock::now();
  const CastProgress report = [&](std::size_t done, std::size_t total) {
    if (!progress) return;
    const double elapsed = secondsSince(t_start);
    std::fprintf(stderr, "\rscan %zu/%zu  %.0f ms/scan  %.0f s left   ", done, total,
                 1000.0 * tot.insert_s / static_cast<double>(done),
                 elapsed / static_cast<double>(done) * static_cast<double>(total - done));
  };
  if (o.inputs.size() == 1 && isDirectory(o.inputs[0])) {
    if (o.frames.empty()) throw CLI::ValidationError("frames", "a KITTI root needs --frames");
    const std::vector<std::size_t> frames = parseFramesOption(o.frames);
    const auto [first, last] = ranks.share(frames.size());
    const KittiWorld world = o.world == "camera" ? KittiWorld::Camera : KittiWorld::Velodyne;
    castKittiFrames(map, KittiSequence{o.inputs[0], o.sequence}, frames, first, last, world, tot,
                    report);
  } else if (isScanSource(o.inputs)) {
    SourceOptions so;
    so.path = o.inputs[0];
    so.frames = o.frames;
    so.topic = o.topic;
    so.reference = o.reference;
    const std::unique_ptr<ScanSource> source = openSource(so);
    const std::vector<std::size_t> frames = selectedFrames(so, *source);
    const std::vector<Eigen::Isometry3d> poses = referenceSensorPoses(*source, frames);
    const auto [first, last] = ranks.share(frames.size());
    castSourceFrames(map, *source, frames, poses, first, last, tot, report);
  } else {
    const auto [first, last] = ranks.share(o.inputs.size());
    castPcdScans(map, o.inputs, first, last, tot, report);
  }
  if (progress) std::fprintf(stderr, "\n");
}

/// The job's totals on rank 0: counts summed, seconds the slowest rank's (insert: summed, for
/// the time per scan).
void reduceTotals(const Ranks& ranks, Totals& tot) {
  std::vector<std::uint64_t> counts = {
      tot.frames, tot.points,     tot.beams,
      tot.cut,    tot.non_finite, static_cast<std::uint64_t>(tot.insert_s * 1e9)};
  std::vector<double> seconds = {tot.load_s, tot.insert_s};
  ranks.sum(counts);
  ranks.max(seconds);
  tot.frames = counts[0];
  tot.points = counts[1];
  tot.beams = counts[2];
  tot.cut = counts[3];
  tot.non_finite = counts[4];
  tot.insert_cpu_s = static_cast<double>(counts[5]) * 1e-9;
  tot.load_s = seconds[0];
  tot.insert_s = seconds[1];
}

/// Options that do not apply to the inputs given are refused, never ignored (issue 24, class 6):
/// a .bt/.ot map is exported as it is (no scan options); PCD scans carry their own pose (no KITTI
/// options); --band only shapes --out-map.
void refuseIgnoredOptions(const OccupancyOptions& o, bool from_file, bool kitti, bool source) {
  const std::vector<std::pair<const char*, bool>> scan_options = {
      {"--resolution", o.resolution_given}, {"--max-range", o.max_range_given},
      {"--frames", !o.frames.empty()},      {"--sequence", o.sequence_given},
      {"--world", o.world_given},           {"--threads", o.threads_given}};
  for (const auto& [option, given] : scan_options) {
    if (!given) continue;
    const std::string name = option;
    if (from_file) {
      throw UsageError(name + ": '" + quoteForMessage(o.inputs[0]) +
                       "' is a map, exported as it is: scan options do not apply to it");
    }
    if (source && (name == "--sequence" || name == "--world")) {
      throw UsageError(name + " selects KITTI scans: '" + quoteForMessage(o.inputs[0]) +
                       "' is a scan source cast at its reference poses");
    }
    if (!kitti && !source && (name == "--frames" || name == "--sequence" || name == "--world")) {
      throw UsageError(name +
                       " selects KITTI scans: the inputs are PCD files (each one's pose is "
                       "its VIEWPOINT)");
    }
  }
  for (const auto& [option, value] :
       {std::pair<const char*, const std::string*>{"--topic", &o.topic},
        {"--reference", &o.reference}}) {
    if (!value->empty() && !source)
      throw UsageError(std::string(option) +
                       " applies to a scan source (a folder, a list, a log or a bag), not to " +
                       (from_file ? "a map"
                        : kitti   ? "a KITTI root"
                                  : "PCD files"));
  }
  if (!o.band.empty() && o.out_map.empty())
    throw UsageError("--band is the height band of --out-map: give --out-map too");
  if (o.pcd_format_given && o.out_cloud.empty())
    throw UsageError(
        "--pcd-format has no effect without --out-cloud: it is the encoding of the "
        "PCD written there");
}

void run(const OccupancyOptions& o, const Ranks& ranks) {
  const bool from_file =
      o.inputs.size() == 1 && (endsWith(o.inputs[0], ".bt") || endsWith(o.inputs[0], ".ot"));
  const bool source = !from_file && isScanSource(o.inputs);
  refuseIgnoredOptions(o, from_file, !from_file && o.inputs.size() == 1 && isDirectory(o.inputs[0]),
                       source);
  if (!o.out_map.empty() && o.band.empty())
    throw CLI::ValidationError("band", "--out-map needs --band zmin,zmax");
  if (!o.out_map.empty() && o.world == "camera")
    throw CLI::ValidationError("world",
                               "the --band is along z: use --world velodyne for --out-map");
  std::pair<double, double> band{0, 0};
  if (!o.band.empty()) band = parseBand(o.band);
  RolePaths inputs = withRole("input", o.inputs);
  if (!o.reference.empty()) inputs.push_back({"--reference", o.reference});
  requireDistinctInputs(inputs);
  if (!from_file && o.inputs.size() == 1 && isDirectory(o.inputs[0]) && !o.frames.empty()) {
    inputs = kittiInputs(o.inputs[0], o.sequence, parseFramesOption(o.frames), true);
  }
  if (source) {
    SourceOptions so;
    so.path = o.inputs[0];
    inputs = sourceInputs(so);
  }
  requireDistinctFiles(inputs,
                       {{"--out", o.out_bt},
                        {"--out-ot", o.out_ot},
                        {"--out-cloud", o.out_cloud},
                        {"--out-map", o.out_map},
                        {"--out-map (its .yaml)", o.out_map.empty() ? "" : yamlOf(o.out_map)},
                        {"--map-preview", o.map_preview}});
  requireExtension("--out", o.out_bt, {".bt"}, "an OctoMap .bt, maximum likelihood");
  requireExtension("--out-ot", o.out_ot, {".ot"}, "an OctoMap .ot, log-odds");
  requireExtension("--out-cloud", o.out_cloud, {".pcd"}, "a PCD cloud");
  requireExtension("--out-map", o.out_map, {".pgm"}, "a map_server PGM with its YAML");
  requireExtension("--map-preview", o.map_preview, {".png"}, "a PNG picture");
  if (!o.map_preview.empty() && o.out_map.empty())
    throw UsageError("--map-preview is a picture of --out-map: give --out-map too");
  Totals tot;
  LogOddsParams params;
  if (!from_file) {
    if (!o.resolution_given || !o.max_range_given)
      throw CLI::ValidationError("resolution", "scans need --resolution and --max-range");
    params.resolution = o.resolution;
    params.max_range = o.max_range;
  }
  try {
    validateLogOddsParams(params);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());  // option values: a usage error
  }
  auto t = std::chrono::steady_clock::now();
  LogOddsMap map = from_file ? readOctomapQuietly(o.inputs[0], exportUse(o)) : LogOddsMap(params);
  if (from_file) tot.load_s = secondsSince(t);
  map.setThreads(o.threads);
  if (!from_file) castScans(o, ranks, map, tot);
  if (ranks.distributed()) {
    map = ranks.reduce(std::move(map));
    reduceTotals(ranks, tot);
    if (!ranks.isRoot()) return;
  }

  // everything that can fail on the data is computed before the first file is written
  t = std::chrono::steady_clock::now();
  TrinaryMap trinary;
  if (!o.out_map.empty()) {
    try {
      trinary = projectBand(map, band.first, band.second);
    } catch (const CapacityError& e) {
      throw CapacityError("--out-map with --band " + o.band + ": " + e.what());
    }
  }
  OutputSet outputs;  // every output or none, committed once the report is printed
  if (!o.out_bt.empty()) writeOctomapQuietly(map, outputs.stage(o.out_bt));
  if (!o.out_ot.empty()) writeOctomapQuietly(map, outputs.stage(o.out_ot));
  if (!o.out_cloud.empty())
    savePcdAtomic(outputs.stage(o.out_cloud), occupiedCenters(map), parsePcdFormat(o.pcd_format));
  if (!o.out_map.empty()) {
    MapServerFiles files = mapServerFiles(o.out_map);
    files.preview_png = o.map_preview;
    writeMapServer(mapServerImage(trinary), files, outputs);
  }
  tot.write_s = secondsSince(t);

  const LogOddsMemory mem = map.memory();
  const std::size_t occupied = map.occupiedVoxels();
  const double insert_s = tot.insert_cpu_s >= 0 ? tot.insert_cpu_s : tot.insert_s;
  const double ms_per_scan =
      tot.frames == 0 ? 0.0 : 1000.0 * insert_s / static_cast<double>(tot.frames);
  if (o.format == "json") {
    nlohmann::json j;
    j["frames"] = tot.frames;
    j["points"] = tot.points;
    j["non_finite"] = tot.non_finite;
    j["beams"] = tot.beams;
    j["beams_cut"] = tot.cut;
    j["resolution"] = map.resolution();
    j["voxels"] = {{"known", map.knownVoxels()},
                   {"occupied", occupied},
                   {"free", map.knownVoxels() - occupied}};
    j["bytes"] = mem.bytes;
    j["bytes_per_known_voxel"] = mem.bytes_per_known_voxel;
    j["seconds"] = {{"load", tot.load_s}, {"insert", tot.insert_s}, {"write", tot.write_s}};
    j["ms_per_scan"] = ms_per_scan;
    if (!o.out_map.empty())
      j["map"] = {{"width", trinary.width},
                  {"height", trinary.height},
                  {"occupied", trinary.occupied},
                  {"free", trinary.free}};
    emit(j.dump(2) + "\n", outputs);
    return;
  }
  Table tab(
      {"frames", "beams", "beams_cut", "known", "occupied", "free", "bytes/voxel", "ms/scan"});
  char bpv[32], ms[32];
  std::snprintf(bpv, sizeof bpv, "%.1f", mem.bytes_per_known_voxel);
  std::snprintf(ms, sizeof ms, "%.1f", ms_per_scan);
  tab.addRow({std::to_string(tot.frames), std::to_string(tot.beams), std::to_string(tot.cut),
              std::to_string(map.knownVoxels()), std::to_string(occupied),
              std::to_string(map.knownVoxels() - occupied), bpv, ms});
  emitTable(tab, "table", outputs);
}

}  // namespace

void addOccupancyCommand(CLI::App& app) {
  auto o = std::make_shared<OccupancyOptions>();
  CLI::App* sub = app.add_subcommand(
      "occupancy", "Ray-cast scans into a log-odds voxel map; OctoMap .bt/.ot, 2D trinary map");
  sub->add_option("input", o->inputs,
                  "A KITTI root (with --frames), a scan source cast at its reference poses (a "
                  "folder of scans with poses.txt, a .txt list, a CARMEN log; --frames "
                  "optional), PCD files (VIEWPOINT = sensor pose), or one .bt/.ot map to export")
      ->required();
  sub->add_option("--resolution", o->resolution, "Voxel edge (m), 0.0001 to 1000")
      ->check(kCellEdge);
  sub->add_option("--max-range", o->max_range, "Beams are cut here and mark no hit (m), > 0")
      ->check(kFinitePositive);
  sub->add_option("--threads", o->threads,
                  "Threads casting each scan's beams (0: all hardware threads); the map does not "
                  "depend on it")
      ->check(countIn(0, 1024))
      ->capture_default_str();
  sub->add_option("--sequence", o->sequence, "KITTI sequence")->capture_default_str();
  sub->add_option("--topic", o->topic, "Bag topic (a scan source that is a ROS bag)");
  sub->add_option("--reference", o->reference,
                  "Poses of the source's scans (KITTI or TUM rows; a bag has none of its own)");
  sub->add_option("--frames", o->frames, "KITTI or scan source frames, e.g. 0-5,15");
  sub->add_option("--world", o->world, "KITTI world: velodyne (z up) or camera (y down)")
      ->check(CLI::IsMember({"camera", "velodyne"}))
      ->capture_default_str();
  sub->add_option("--out", o->out_bt, "Write OctoMap .bt (maximum likelihood)")->check(kOutputFile);
  sub->add_option("--out-ot", o->out_ot, "Write OctoMap .ot (log-odds)")->check(kOutputFile);
  sub->add_option("--out-cloud", o->out_cloud, "Write the occupied voxel centres (.pcd)")
      ->check(kOutputFile);
  sub->add_option("--out-map", o->out_map, "Write a trinary map_server map (.pgm + .yaml)")
      ->check(kOutputFile);
  sub->add_option("--band", o->band, "Height band of --out-map: zmin,zmax (m)");
  sub->add_option("--map-preview", o->map_preview, "Also write --out-map as PNG")
      ->check(kOutputFile);
  addPcdFormatOption(*sub, o->pcd_format);
  sub->add_flag("--distributed", o->distributed,
                "Run as MPI ranks (mpirun -np N metricmap occupancy ...): each rank casts its "
                "share of the frames or files, voxels are merged by tile; rank 0 writes");
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    OccupancyOptions opts = *o;
    opts.resolution_given = sub->count("--resolution") > 0;
    opts.max_range_given = sub->count("--max-range") > 0;
    opts.sequence_given = sub->count("--sequence") > 0;
    opts.world_given = sub->count("--world") > 0;
    opts.threads_given = sub->count("--threads") > 0;
    opts.pcd_format_given = sub->count("--pcd-format") > 0;
    const bool from_file = opts.inputs.size() == 1 &&
                           (endsWith(opts.inputs[0], ".bt") || endsWith(opts.inputs[0], ".ot"));
    if (opts.distributed && from_file)
      throw UsageError("--distributed casts scans; a .bt/.ot input is exported by one process");
    const Ranks ranks(opts.distributed);
    ranks.run([&] { run(opts, ranks); });
  });
}

}  // namespace metricmap::cli
