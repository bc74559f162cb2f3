// metricmap view FILE...: points with octree leaves or grid cells, interactive or a screenshot.
#include <cstdlib>
#include <memory>
#include <sstream>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/octree/adaptive_octree.h"
#include "view_scene.h"

namespace metricmap::cli {
namespace {

struct ViewOptions {
  std::vector<std::string> files;
  bool octree = false, grid = false, show_empty = false;
  long long max_points = 100;
  float min_cell_size = 1.0f, cell_size = 1.0f;
  std::string color_by = "height", screenshot, window_size = "1280x800", camera = "iso", up = "z";
};

using CloudRGB = pcl::PointCloud<pcl::PointXYZRGB>;

void run(const ViewOptions& o) {
  int width = 0, height = 0;
  char x = 0;
  std::istringstream ws(o.window_size);
  if (!(ws >> width >> x >> height) || x != 'x' || width < 16 || height < 16 || width > 16384 ||
      height > 16384) {
    throw CLI::ValidationError("--window-size",
                               "expected WxH between 16 and 16384, got '" + o.window_size + "'");
  }
  if (o.color_by == "count" && !o.octree) {
    throw CLI::ValidationError("--color-by",
                               "count needs --octree (points take their leaf's count)");
  }
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    throw std::runtime_error(
        "no X display: set DISPLAY, or run under xvfb-run (--screenshot renders offscreen but "
        "still needs an X server)");
  }
  auto cloud = std::make_shared<CloudRGB>();
  for (const std::string& f : o.files) {
    CloudRGB part;
    const LoadReport r = loadCloud(f, part);
    for (const auto& w : r.warnings) std::cerr << "warning: " << w << "\n";
    *cloud += part;
  }
  std::ostringstream title;
  title << (o.files.size() == 1 ? o.files.front() : std::to_string(o.files.size()) + " files")
        << " | " << cloud->size() << " points";
  std::vector<CountedBox> boxes;
  std::vector<double> point_counts;
  if (o.octree) {
    AdaptiveOctree<pcl::PointXYZRGB> octree;
    octree.setMaxPointsPerLeaf(static_cast<std::size_t>(o.max_points));
    octree.setMinCellSize(o.min_cell_size);
    octree.setInputCloud(cloud);
    octree.compute();
    point_counts.assign(cloud->size(), 0.0);
    const auto& nodes = octree.getNodes();
    for (std::size_t id = 0; id < nodes.size(); ++id) {
      const OctreeNode& n = nodes[id];
      if (!n.isLeaf() || (n.count == 0 && !o.show_empty)) continue;
      boxes.push_back({n.min, n.max, static_cast<double>(n.count)});
      for (int i : octree.getPointIndices(id)) point_counts[static_cast<std::size_t>(i)] = n.count;
    }
    const OctreeStatistics& s = octree.getStatistics();
    title << " | octree max_points " << o.max_points << ", min_cell " << o.min_cell_size << ": "
          << s.occupied_leaves << " occupied / " << s.leaf_nodes << " leaves";
  }
  if (o.grid) {
    OccupancyGrid<pcl::PointXYZRGB> grid;
    grid.setCellSize(o.cell_size);
    grid.setInputCloud(cloud);
    grid.compute();
    for (const GridCell& c : grid.getCells()) {
      const Eigen::Vector3d lo = grid.getCellMin(c.index);
      boxes.push_back(
          {lo, lo + Eigen::Vector3d::Constant(o.cell_size), static_cast<double>(c.count)});
    }
    title << " | grid cell " << o.cell_size << ": " << grid.getStatistics().occupied_cells
          << " occupied cells";
  }
  SceneOptions so;
  so.title = title.str();
  so.color_by = o.color_by;
  so.up_axis = o.up == "x" ? 0 : (o.up == "y" ? 1 : 2);
  so.camera = o.camera;
  const Scene scene = buildScene(*cloud, point_counts, boxes, so);
  if (!o.screenshot.empty()) {
    writeScreenshot(scene, width, height, o.screenshot);
  } else {
    runInteractive(scene, width, height);
  }
}

}  // namespace

void addViewCommand(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* sub = app.add_subcommand("view", "3D view of points with octree leaves or grid cells");
  sub->add_option("files", o->files, "Point clouds (.pcd, .ply, .bin); several are merged")
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
  sub->add_option("--color-by", o->color_by, "Point colours")
      ->check(CLI::IsMember({"height", "rgb", "count"}))
      ->capture_default_str();
  sub->add_option("--up", o->up, "Axis that is up (the study's scans: y)")
      ->check(CLI::IsMember({"x", "y", "z"}))
      ->capture_default_str();
  sub->add_option("--screenshot", o->screenshot, "Render offscreen to this PNG and exit");
  sub->add_option("--window-size", o->window_size, "WxH")->capture_default_str();
  sub->add_option("--camera", o->camera, "Initial view")
      ->check(CLI::IsMember({"top", "side", "iso"}))
      ->capture_default_str();
  sub->callback([o] { run(*o); });
}

}  // namespace metricmap::cli
