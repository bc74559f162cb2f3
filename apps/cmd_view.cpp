// metricmap view FILE...: points with octree leaves or grid cells, interactive or a screenshot.
#include <cstdlib>
#include <memory>
#include <sstream>
#include <utility>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/lines_json.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "metricmap/occupancy/octomap_quiet.h"
#include "metricmap/viz/view_content.h"
#include "view_options.h"
#include "viz_loader.h"

namespace metricmap::cli {
namespace {

using CloudRGB = pcl::PointCloud<pcl::PointXYZRGB>;

void loadScanLog(const std::string& f, const ViewOptions& o, CloudRGB& out) {
  const ScanLineFormat mines = urg04lxMinesFormat();
  const ScanLog log = readScanLog(f, o.preset.empty() ? nullptr : &mines);
  if (static_cast<std::size_t>(o.scan) >= log.scans.size()) {
    throw std::invalid_argument("--scan " + std::to_string(o.scan) + " is out of range: " + f +
                                " has " + std::to_string(log.scans.size()) + " scan(s)");
  }
  viz::appendScanPoints(scanToCloud(log.scans[static_cast<std::size_t>(o.scan)]), out);
}

void run(const ViewOptions& o, const CLI::App& app) {
  refuseIgnoredViewOptions(o, app);
  const auto [width, height] = parseWindowSize(o.window_size);
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
  checkOctomapBudget(o);
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    throw std::runtime_error(
        "no X display: set DISPLAY, or run under xvfb-run (--screenshot renders offscreen but "
        "still needs an X server)");
  }
  viz::ViewRequest request;
  auto cloud = std::make_shared<CloudRGB>();
  bool scan_logs_only = true;
  for (const std::string& f : o.files) {
    CloudRGB part;
    if (isOctomapFile(f)) {
      const LogOddsMap map = readOctomapQuietly(f, LogOddsParams(), cubeUse(o.free));
      viz::addMapVoxels(map, f, o.free, request.occupied, request.free);
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
  std::ostringstream title;
  title << (o.files.size() == 1 ? o.files.front() : std::to_string(o.files.size()) + " files")
        << (cloud->empty() ? "" : " | " + std::to_string(cloud->size()) + " points");
  if (request.occupied.size > 0) {
    title << " | " << request.occupied.centers.size() << " occupied";
    if (o.free) title << ", " << request.free.centers.size() << " free";
    title << " voxels of " << request.occupied.size << " m";
  }
  viz::StructureBoxes boxes = viz::structureBoxes(cloud, structureSettings(o));
  title << boxes.title;
  if (!segments.empty())  // segments live in a scan's plane: looked at from above
    title << " | " << segments.size() << " segments (scan " << o.scan << ")";
  viz::SceneOptions& so = request.options;
  so.title = title.str();
  // A 2D scan is flat: height colouring would paint it one colour; use its light grey.
  so.color_by = scan_logs_only && o.color_by == "height" ? "rgb" : o.color_by;
  so.up_axis = o.up == "x" ? 0 : (o.up == "y" ? 1 : 2);
  so.camera = segments.empty() ? o.camera : "top";
  request.cloud = cloud.get();
  request.point_counts = std::move(boxes.point_counts);
  request.boxes = std::move(boxes.boxes);
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
