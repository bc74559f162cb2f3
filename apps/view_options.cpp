#include "view_options.h"

#include <cstdint>
#include <stdexcept>

#include "cli_common.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/occupancy/octomap_quiet.h"

namespace metricmap::cli {
namespace {

/// What one drawn voxel costs: its centre twice (the map's list, the request), VTK's point and
/// height scalar, and the glyph mapper's per-cube matrix, colour and normal matrix on the way to
/// the renderer. A tree of a few dozen bytes can stand for 2^27 voxels: checked before drawing.
constexpr std::uint64_t kCubeBytes = 256;

}  // namespace

bool isScanLog(const std::string& f, const ViewOptions& o) {
  return !o.preset.empty() || detectScanLog(f) != ScanLogKind::Unknown;
}

bool isOctomapFile(const std::string& f) {
  const auto dot = f.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : f.substr(dot);
  return ext == ".bt" || ext == ".ot";
}

OctomapUse cubeUse(bool with_free) {
  OctomapUse use;
  use.bytes_per_occupied_voxel = kCubeBytes;
  use.bytes_per_free_voxel = with_free ? kCubeBytes : 0;
  use.purpose = with_free ? "occupied and free voxels drawn as cubes" : "drawn as cubes";
  return use;
}

void refuseIgnoredViewOptions(const ViewOptions& o, const CLI::App& app) {
  refuseIgnored(app, "--max-points", o.octree,
                "without --octree: it is the octree's split threshold");
  refuseIgnored(app, "--min-cell-size", o.octree,
                "without --octree: it is the smallest octree node that may split");
  refuseIgnored(app, "--show-empty", o.octree, "without --octree: it draws empty octree leaves");
  refuseIgnored(app, "--cell-size", o.grid, "without --grid: it is the edge of the grid's cells");
  bool maps = false, logs = false, only_logs = true;
  for (const std::string& f : o.files) {
    const bool map = isOctomapFile(f);
    // a scan log is only told apart by reading it: only when an option depends on it
    const bool log =
        !map && (app.count("--scan") > 0 || app.count("--color-by") > 0) && isScanLog(f, o);
    maps = maps || map;
    logs = logs || log;
    only_logs = only_logs && log;
  }
  refuseIgnored(app, "--free", maps,
                "without an OctoMap file (.bt, .ot): it draws the map's free voxels");
  refuseIgnored(app, "--camera", o.segments.empty() || o.camera == "top",
                "with --segments: segments are drawn seen from above (top)");
  refuseIgnored(app, "--scan", logs || !o.segments.empty(),
                "without a scan log or --segments: it picks one scan of a log");
  if (app.count("--color-by") > 0 && o.color_by == "height" && only_logs) {
    throw UsageError(
        "--color-by height has no effect on scan logs alone: a 2D scan lies at z = 0 (its "
        "points are drawn grey)");
  }
}

viz::StructureSettings structureSettings(const ViewOptions& o) {
  viz::StructureSettings s;
  s.octree = o.octree;
  s.max_points = static_cast<std::size_t>(o.max_points);
  s.min_cell_size = o.min_cell_size;
  s.show_empty = o.show_empty;
  s.grid = o.grid;
  s.cell_size = o.cell_size;
  return s;
}

std::pair<int, int> parseWindowSize(const std::string& text) {
  const std::size_t x = text.find('x');
  try {
    if (x == std::string::npos) throw std::invalid_argument("no 'x'");
    return {static_cast<int>(parseInteger(text.substr(0, x), "width", 16, 16384)),
            static_cast<int>(parseInteger(text.substr(x + 1), "height", 16, 16384))};
  } catch (const std::invalid_argument&) {
    throw CLI::ValidationError(
        "--window-size", "expected WxH between 16 and 16384, got '" + quoteForMessage(text) + "'");
  }
}

void checkOctomapBudget(const ViewOptions& o) {
  std::uint64_t voxel_bytes = 0, voxels = 0;
  for (const std::string& f : o.files) {
    if (!isOctomapFile(f)) continue;
    const OctomapExpansion e = inspectOctomapQuietly(f, LogOddsParams(), cubeUse(o.free));
    voxel_bytes += e.map_bytes + e.use_bytes;
    voxels += o.free ? e.voxels : e.occupied_voxels;
  }
  checkMemory(voxel_bytes, 1,
              "the OctoMap files' " + std::to_string(voxels) + " voxels drawn as cubes");
}

}  // namespace metricmap::cli
