// metricmap grid FILE --cell-size S: occupancy grid statistics, cell means, per-cell CSV.
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "stats_json.h"
#include "table.h"

namespace metricmap::cli {
namespace {

struct GridOptions {
  std::string file;
  float cell_size = 0.0f;
  std::string origin = "cloud-min";
  std::string out, cells, format = "table", pcd_format = "binary";
};

std::string cellsCsv(const std::vector<GridCell>& cells) {
  std::ostringstream os;
  os.precision(9);
  os << "ix,iy,iz,count,mean_x,mean_y,mean_z\n";
  for (const GridCell& c : cells) {
    os << c.index[0] << "," << c.index[1] << "," << c.index[2] << "," << c.count << ","
       << c.mean.x() << "," << c.mean.y() << "," << c.mean.z() << "\n";
  }
  return os.str();
}

void runGrid(const GridOptions& o) {
  requireDistinctOutputs({{"--out", o.out}, {"--cells", o.cells}});
  const LoadedCloud loaded = loadTimed(o.file);
  const auto& cloud = loaded.cloud;

  const auto t1 = std::chrono::steady_clock::now();
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(o.cell_size);
  grid.setOrigin(o.origin == "world" ? GridOrigin::WorldAligned : GridOrigin::CloudMinimum);
  grid.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ> means;
  grid.filter(means);
  const double grid_s = secondsSince(t1);

  OutputSet outputs;
  if (!o.out.empty()) savePcdAtomic(outputs.stage(o.out), means, parsePcdFormat(o.pcd_format));
  if (!o.cells.empty()) writeTextAtomic(outputs.stage(o.cells), cellsCsv(grid.getCells()));
  outputs.commit();

  const GridStatistics& s = grid.getStatistics();
  if (o.format == "json") {
    nlohmann::json j = {{"file", o.file},
                        {"points", cloud->size()},
                        {"cell_size", o.cell_size},
                        {"origin", o.origin},
                        {"grid", s},
                        {"seconds", {{"load", loaded.seconds}, {"grid", grid_s}}}};
    emit(j.dump(2) + "\n", "");
    return;
  }
  Table t({"file", "cell_size", "origin", "points", "total_cells", "occupied_cells", "empty_cells",
           "mean_points_per_occupied_cell"});
  t.addRow({o.file, readable(o.cell_size), o.origin, std::to_string(s.points),
            std::to_string(s.total_cells), std::to_string(s.occupied_cells),
            std::to_string(s.empty_cells), fixed(s.mean_points_per_occupied_cell, 2)});
  emitTable(t, o.format);
}

}  // namespace

void addGridCommand(CLI::App& app) {
  auto o = std::make_shared<GridOptions>();
  CLI::App* sub = app.add_subcommand("grid", "Occupancy grid: cell counts and means");
  sub->add_option("file", o->file, "Point cloud (.pcd, .ply, .bin)")->required();
  sub->add_option("--cell-size", o->cell_size, "Cell edge in metres")
      ->required()
      ->check(kFinitePositiveFloat);
  sub->add_option("--origin", o->origin,
                  "cloud-min: index = floor((p - min)/cell) (the study's); "
                  "world: floor(p/cell) (pcl::VoxelGrid's)")
      ->check(CLI::IsMember({"cloud-min", "world"}))
      ->capture_default_str();
  sub->add_option("--out", o->out, "Write the cell means as a PCD")->check(kOutputFile);
  sub->add_option("--cells", o->cells, "Write one CSV row per occupied cell")->check(kOutputFile);
  addFormatOption(*sub, o->format, {"table", "csv", "json"});
  addPcdFormatOption(*sub, o->pcd_format);
  sub->callback([o] { runGrid(*o); });
}

}  // namespace metricmap::cli
