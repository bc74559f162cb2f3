#include "occupancy_options.h"

#include <CLI/CLI.hpp>

#include "cli_common.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/io/map_server.h"
#include "metricmap/occupancy/octomap_export_use.h"
#include "sequence_options.h"

namespace metricmap::cli {
namespace {

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

/// Options that do not apply to the inputs given are refused, never ignored:
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

}  // namespace

OccupancyPlan checkOccupancyOptions(const OccupancyOptions& o, OccupancyInputKind kind) {
  const bool from_file = kind == OccupancyInputKind::OctomapFile;
  const bool kitti = kind == OccupancyInputKind::KittiRoot;
  const bool source = kind == OccupancyInputKind::ScanSource;
  refuseIgnoredOptions(o, from_file, kitti, source);
  if (!o.out_map.empty() && o.band.empty())
    throw CLI::ValidationError("band", "--out-map needs --band zmin,zmax");
  if (!o.out_map.empty() && o.world == "camera")
    throw CLI::ValidationError("world",
                               "the --band is along z: use --world velodyne for --out-map");
  OccupancyPlan plan;
  if (!o.band.empty()) plan.band = parseBand(o.band);
  RolePaths inputs = withRole("input", o.inputs);
  if (!o.reference.empty()) inputs.push_back({"--reference", o.reference});
  requireDistinctInputs(inputs);
  if (kitti && !o.frames.empty()) {
    inputs = kittiInputs(o.inputs[0], o.sequence, parseFramesOption(o.frames), true);
  }
  if (source) {
    SourceOptions so;
    so.path = o.inputs[0];
    inputs = sourceInputs(so);
  }
  const std::string yaml = o.out_map.empty() ? "" : mapServerFiles(o.out_map).yaml;
  requireDistinctFiles(inputs, {{"--out", o.out_bt},
                                {"--out-ot", o.out_ot},
                                {"--out-cloud", o.out_cloud},
                                {"--out-map", o.out_map},
                                {"--out-map (its .yaml)", yaml},
                                {"--map-preview", o.map_preview}});
  requireExtension("--out", o.out_bt, {".bt"}, "an OctoMap .bt, maximum likelihood");
  requireExtension("--out-ot", o.out_ot, {".ot"}, "an OctoMap .ot, log-odds");
  requireExtension("--out-cloud", o.out_cloud, {".pcd"}, "a PCD cloud");
  requireExtension("--out-map", o.out_map, {".pgm"}, "a map_server PGM with its YAML");
  requireExtension("--map-preview", o.map_preview, {".png"}, "a PNG picture");
  if (!o.map_preview.empty() && o.out_map.empty())
    throw UsageError("--map-preview is a picture of --out-map: give --out-map too");
  if (!from_file) {
    if (!o.resolution_given || !o.max_range_given)
      throw CLI::ValidationError("resolution", "scans need --resolution and --max-range");
    plan.params.resolution = o.resolution;
    plan.params.max_range = o.max_range;
  }
  try {
    validateLogOddsParams(plan.params);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());  // option values: a usage error
  }
  return plan;
}

OctomapUse occupancyExportUse(const OccupancyOptions& o) {
  std::vector<std::string> trees, clouds;
  if (!o.out_bt.empty()) trees.emplace_back("--out");
  if (!o.out_ot.empty()) trees.emplace_back("--out-ot");
  if (!o.out_cloud.empty()) clouds.emplace_back("--out-cloud");
  return octomapExportUse(trees, clouds);
}

}  // namespace metricmap::cli
