// metricmap view FILE...: points with octree leaves or grid cells, interactive or a screenshot.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <utility>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"

#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/lines_json.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "metricmap/viz/scene_content.h"
#include "octomap_quiet.h"
#include "viz_loader.h"

namespace metricmap::cli {
namespace {

struct ViewOptions {
  std::vector<std::string> files;
  bool octree = false, grid = false, show_empty = false, free = false;
  long long max_points = 100;
  float min_cell_size = 1.0f, cell_size = 1.0f;
  std::string color_by = "height", screenshot, window_size = "1280x800", camera = "iso", up = "z";
  std::string segments, preset;
  long long scan = 0;
};

using CloudRGB = pcl::PointCloud<pcl::PointXYZRGB>;

/// Scan logs (.csv angle,range; CARMEN; --preset logs) become 2D clouds at z = 0.
bool isScanLog(const std::string& f, const ViewOptions& o) {
  return !o.preset.empty() || detectScanLog(f) != ScanLogKind::Unknown;
}

void loadScanLog(const std::string& f, const ViewOptions& o, CloudRGB& out) {
  const ScanLineFormat mines = urg04lxMinesFormat();
  const ScanLog log = readScanLog(f, o.preset.empty() ? nullptr : &mines);
  if (static_cast<std::size_t>(o.scan) >= log.scans.size()) {
    throw std::invalid_argument("--scan " + std::to_string(o.scan) + " is out of range: " + f +
                                " has " + std::to_string(log.scans.size()) + " scan(s)");
  }
  for (const auto& p : scanToCloud(log.scans[static_cast<std::size_t>(o.scan)])) {
    if (!std::isfinite(p.x)) continue;
    pcl::PointXYZRGB q;
    q.x = p.x;
    q.y = p.y;
    q.z = 0.0f;
    q.r = q.g = q.b = 200;
    out.push_back(q);
  }
}

bool isOctomapFile(const std::string& f) {
  const auto dot = f.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : f.substr(dot);
  return ext == ".bt" || ext == ".ot";
}

/// What one drawn voxel costs: its centre twice (the map's list, the request), VTK's point and
/// height scalar, and the glyph mapper's per-cube matrix, colour and normal matrix on the way to
/// the renderer. A tree of a few dozen bytes can stand for 2^27 voxels: checked before drawing.
constexpr std::uint64_t kCubeBytes = 256;

OctomapUse cubeUse(bool with_free) {
  OctomapUse use;
  use.bytes_per_occupied_voxel = kCubeBytes;
  use.bytes_per_free_voxel = with_free ? kCubeBytes : 0;
  use.purpose = with_free ? "occupied and free voxels drawn as cubes" : "drawn as cubes";
  return use;
}

/// OctoMap .bt/.ot: occupied voxels (and free ones with --free) as cubes.
void addOctomap(const std::string& f, bool with_free, viz::ViewRequest& request) {
  const LogOddsMap map = readOctomapQuietly(f, cubeUse(with_free));
  if (request.occupied.size > 0 && request.occupied.size != map.resolution()) {
    throw InputError(f + ": resolution " + std::to_string(map.resolution()) +
                     " differs from the other map's " + std::to_string(request.occupied.size));
  }
  request.occupied.size = request.free.size = map.resolution();
  for (const auto& c : voxelCenters(map, true)) request.occupied.centers.push_back(c);
  if (with_free)
    for (const auto& c : voxelCenters(map, false)) request.free.centers.push_back(c);
}

/// Options that would have no effect on this view are refused, never dropped (issue 24, class 6).
void refuseIgnoredOptions(const ViewOptions& o, const CLI::App& app) {
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

void run(const ViewOptions& o, const CLI::App& app) {
  refuseIgnoredOptions(o, app);
  int width = 0, height = 0;
  const std::size_t x = o.window_size.find('x');
  try {
    if (x == std::string::npos) throw std::invalid_argument("no 'x'");
    width = static_cast<int>(parseInteger(o.window_size.substr(0, x), "width", 16, 16384));
    height = static_cast<int>(parseInteger(o.window_size.substr(x + 1), "height", 16, 16384));
  } catch (const std::invalid_argument&) {
    throw CLI::ValidationError("--window-size", "expected WxH between 16 and 16384, got '" +
                                                    quoteForMessage(o.window_size) + "'");
  }
  // VTK keeps several full-size buffers (colour, depth, offscreen target, screenshot copy).
  checkMemory(static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height), 32,
              "--window-size " + o.window_size);
  if (o.color_by == "count" && !o.octree) {
    throw CLI::ValidationError("--color-by",
                               "count needs --octree (points take their leaf's count)");
  }
  {
    RolePaths inputs = withRole("input", o.files);
    requireDistinctInputs(inputs);
    inputs.emplace_back("--segments file", o.segments);
    requireDistinctFiles(inputs, {{"--screenshot", o.screenshot}});
    requireExtension("--screenshot", o.screenshot, {".png"}, "a PNG picture");
  }
  // Every OctoMap file's voxels, expanded and drawn, within the budget: checked from the trees'
  // leaves before anything is expanded or a window opened.
  std::uint64_t voxel_bytes = 0, voxels = 0;
  for (const std::string& f : o.files) {
    if (!isOctomapFile(f)) continue;
    const OctomapExpansion e = inspectOctomapQuietly(f, cubeUse(o.free));
    voxel_bytes += e.map_bytes + e.use_bytes;
    voxels += o.free ? e.voxels : e.occupied_voxels;
  }
  checkMemory(voxel_bytes, 1,
              "the OctoMap files' " + std::to_string(voxels) + " voxels drawn as cubes");
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    throw std::runtime_error(
        "no X display: set DISPLAY, or run under xvfb-run (--screenshot renders offscreen but "
        "still needs an X server)");
  }
  viz::ViewRequest request;
  auto cloud = std::make_shared<CloudRGB>();
  std::string title_suffix;
  bool scan_logs_only = true;
  for (const std::string& f : o.files) {
    CloudRGB part;
    if (isOctomapFile(f)) {
      addOctomap(f, o.free, request);
    } else if (isScanLog(f, o)) {
      loadScanLog(f, o, part);
    } else {
      scan_logs_only = false;
      const LoadReport r = loadCloud(f, part);
      for (const auto& w : r.warnings) std::cerr << "warning: " << w << "\n";
    }
    *cloud += part;
  }
  const std::vector<viz::DrawnSegment> segments = o.segments.empty()
                                                      ? std::vector<viz::DrawnSegment>()
                                                      : readLineSegmentsJson(o.segments, o.scan);
  if (!segments.empty()) {
    // Segments live in a scan's plane: look at it from above.
    title_suffix =
        " | " + std::to_string(segments.size()) + " segments (scan " + std::to_string(o.scan) + ")";
  }
  std::ostringstream title;
  title << (o.files.size() == 1 ? o.files.front() : std::to_string(o.files.size()) + " files")
        << (cloud->empty() ? "" : " | " + std::to_string(cloud->size()) + " points");
  if (request.occupied.size > 0) {
    title << " | " << request.occupied.centers.size() << " occupied";
    if (o.free) title << ", " << request.free.centers.size() << " free";
    title << " voxels of " << request.occupied.size << " m";
  }
  std::vector<viz::CountedBox> boxes;
  std::vector<double> point_counts;
  if (o.octree) {
    const viz::OctreeBoxes ob = viz::octreeBoxes(cloud, static_cast<std::size_t>(o.max_points),
                                                 o.min_cell_size, o.show_empty);
    boxes = ob.boxes;
    point_counts = ob.point_counts;
    title << " | octree max_points " << o.max_points << ", min_cell " << o.min_cell_size << ": "
          << ob.statistics.occupied_leaves << " occupied / " << ob.statistics.leaf_nodes
          << " leaves";
  }
  if (o.grid) {
    const viz::GridBoxes gb = viz::gridBoxes(cloud, o.cell_size);
    boxes.insert(boxes.end(), gb.boxes.begin(), gb.boxes.end());
    title << " | grid cell " << o.cell_size << ": " << gb.statistics.occupied_cells
          << " occupied cells";
  }
  viz::SceneOptions& so = request.options;
  so.title = title.str() + title_suffix;
  // A 2D scan is flat: height colouring would paint it one colour; use its light grey.
  so.color_by = scan_logs_only && o.color_by == "height" ? "rgb" : o.color_by;
  so.up_axis = o.up == "x" ? 0 : (o.up == "y" ? 1 : 2);
  so.camera = segments.empty() ? o.camera : "top";
  request.cloud = cloud.get();
  request.point_counts = std::move(point_counts);
  request.boxes = std::move(boxes);
  request.segments = segments;
  request.width = width;
  request.height = height;
  request.screenshot = o.screenshot;
  drawingModule().show(request);
}

}  // namespace

void addViewCommand(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* sub = app.add_subcommand("view", "3D view of points with octree leaves or grid cells");
  sub->add_option(
         "files", o->files,
         "Point clouds (.pcd, .ply, .bin, .npy), scan logs or OctoMap maps (.bt, .ot); several "
         "are merged")
      ->required();
  sub->add_flag("--octree", o->octree, "Draw the adaptive octree's leaves");
  sub->add_option("--max-points", o->max_points, "Octree: split above this many points")
      ->check(kCount)
      ->capture_default_str();
  sub->add_option("--min-cell-size", o->min_cell_size, "Octree: smallest edge that may split")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_flag("--grid", o->grid, "Draw the occupied grid cells");
  sub->add_option("--cell-size", o->cell_size, "Grid cell edge")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_flag("--show-empty", o->show_empty, "Also draw empty octree leaves");
  sub->add_flag("--free", o->free, "OctoMap files: also draw free voxels (translucent)");
  sub->add_option("--color-by", o->color_by, "Point colours")
      ->check(CLI::IsMember({"height", "rgb", "count"}))
      ->capture_default_str();
  sub->add_option("--up", o->up, "Axis that is up (the study's scans: y)")
      ->check(CLI::IsMember({"x", "y", "z"}))
      ->capture_default_str();
  sub->add_option("--segments", o->segments,
                  "Draw the segments of `metricmap lines --format json` (scan --scan) at z = 0");
  sub->add_option("--scan", o->scan, "Scan of a scan log and of --segments (0-based)")
      ->check(kCount);
  sub->add_option("--preset", o->preset, "FILE is a scan-per-line log of this layout")
      ->check(CLI::IsMember({"urg04lx-mines"}));
  sub->add_option("--screenshot", o->screenshot, "Render offscreen to this PNG and exit")
      ->check(kOutputFile);
  sub->add_option("--window-size", o->window_size, "WxH")->capture_default_str();
  sub->add_option("--camera", o->camera, "Initial view")
      ->check(CLI::IsMember({"top", "side", "iso"}))
      ->capture_default_str();
  sub->callback([o, sub] { run(*o, *sub); });
}

}  // namespace metricmap::cli
