// metricmap grid FILE... --cell-size S: occupancy grid statistics, cell means, per-cell CSV.
// Several files are one input (concatenated). With --distributed (under mpirun) each rank bins
// its share of the files and the cells are reduced over MPI (ranks.h); with the default
// --origin cloud-min the ranks first agree on the minimum of the whole input (one all-reduce).
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/grid/grid_accumulator.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cell_csv.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "ranks.h"
#include "stats_json.h"
#include "table.h"

namespace metricmap::cli {
namespace {

struct GridOptions {
  std::vector<std::string> files;
  float cell_size = 0.0f;
  std::string origin = "cloud-min";
  bool distributed = false;
  unsigned threads = 0;  ///< 0: all hardware threads (with --distributed: those of the rank)
  std::string out, cells, format = "table", pcd_format = "binary";
};

/// What a build gives the outputs, from one process or from the ranks.
struct GridOutcome {
  std::uint64_t input_points = 0;
  GridStatistics stats;
  std::vector<GridCell> cells;
  pcl::PointCloud<pcl::PointXYZ> means;
  double load_s = 0.0, grid_s = 0.0;
};

void emitGrid(const GridOptions& o, const GridOutcome& g) {
  OutputSet outputs;  // committed once the report is printed
  if (!o.out.empty()) savePcdAtomic(outputs.stage(o.out), g.means, parsePcdFormat(o.pcd_format));
  if (!o.cells.empty()) writeTextAtomic(outputs.stage(o.cells), gridCellsCsv(g.cells));

  const GridStatistics& s = g.stats;
  std::string files = o.files[0];
  for (std::size_t i = 1; i < o.files.size(); ++i) files += "," + o.files[i];
  if (o.format == "json") {
    nlohmann::json j = {{"points", g.input_points},
                        {"cell_size", o.cell_size},
                        {"origin", o.origin},
                        {"grid", s},
                        {"seconds", {{"load", g.load_s}, {"grid", g.grid_s}}}};
    if (o.files.size() == 1) {
      j["file"] = o.files[0];
    } else {
      j["files"] = o.files;
    }
    emit(j.dump(2) + "\n", outputs);
    return;
  }
  Table t({"file", "cell_size", "origin", "points", "total_cells", "occupied_cells", "empty_cells",
           "mean_points_per_occupied_cell"});
  t.addRow({files, readable(o.cell_size), o.origin, std::to_string(s.points),
            std::to_string(s.total_cells), std::to_string(s.occupied_cells),
            std::to_string(s.empty_cells), fixed(s.mean_points_per_occupied_cell, 2)});
  emitTable(t, o.format, outputs);
}

/// One process: the files concatenated, one build (any origin).
GridOutcome buildOne(const GridOptions& o) {
  GridOutcome g;
  LoadedCloud loaded = loadTimed(o.files[0]);
  g.load_s = loaded.seconds;
  for (std::size_t i = 1; i < o.files.size(); ++i) {
    const LoadedCloud more = loadTimed(o.files[i]);
    g.load_s += more.seconds;
    *loaded.cloud += *more.cloud;
  }
  g.input_points = loaded.cloud->size();
  const auto t1 = std::chrono::steady_clock::now();
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(o.cell_size);
  grid.setOrigin(o.origin == "world" ? GridOrigin::WorldAligned : GridOrigin::CloudMinimum);
  grid.setNumberOfThreads(o.threads);
  grid.setInputCloud(loaded.cloud);
  grid.filter(g.means);
  g.grid_s = secondsSince(t1);
  g.stats = grid.getStatistics();
  g.cells = grid.getCells();
  return g;
}

/// The slowest rank's seconds (load, and build + exchange since t0), on rank 0.
void finishSeconds(const Ranks& ranks, GridOutcome& g, std::chrono::steady_clock::time_point t0) {
  g.grid_s = secondsSince(t0) - g.load_s;
  std::vector<double> seconds = {g.load_s, g.grid_s};
  ranks.max(seconds);
  g.load_s = seconds[0];
  g.grid_s = seconds[1];
}

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/// Per-axis minimum of the cloud's finite points, as the grid kernel takes it (+inf on every
/// axis when no point is finite).
std::vector<double> finiteMinimum(const Cloud& cloud) {
  std::vector<double> lo(3, std::numeric_limits<double>::infinity());
  for (const pcl::PointXYZ& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    lo[0] = std::min(lo[0], static_cast<double>(p.x));
    lo[1] = std::min(lo[1], static_cast<double>(p.y));
    lo[2] = std::min(lo[2], static_cast<double>(p.z));
  }
  return lo;
}

/// A GridOrigin::CloudMinimum build of one rank's share whose indices are those of the
/// one-process build of the whole input: the cells start at `job_min`, the minimum over every
/// rank's points (an all-reduce), not at the share's own minimum. The kernel takes the minimum
/// of its input, so a rank whose minimum is above the job's bins its points with one more point
/// at `job_min` (the same kernel, the same snapping to cell boundaries), then takes that point out
/// of its cell: the first one, whose index is the smallest on every axis. The layout's origin is
/// set to 0 for GridAccumulator::add, which merges cells by index.
GridResult jobMinimumPart(OccupancyGrid<pcl::PointXYZ>& grid, const Cloud::Ptr& cloud,
                          const std::vector<double>& job_min) {
  const std::vector<double> mine = finiteMinimum(*cloud);
  const bool extra = std::isfinite(mine[0]) && mine != job_min;
  if (extra) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(job_min[0]), static_cast<float>(job_min[1]),
                                   static_cast<float>(job_min[2])));
    cloud->width = static_cast<std::uint32_t>(cloud->size());
    cloud->height = 1;
  }
  grid.setOrigin(GridOrigin::CloudMinimum);
  grid.setInputCloud(cloud);
  grid.compute();
  GridResult part{grid.getLayout(), grid.getCells(), grid.getStatistics()};
  if (extra) {
    cloud->points.pop_back();
    cloud->width = static_cast<std::uint32_t>(cloud->size());
    GridCell& first = part.cells.front();
    if (first.count == 1) {
      part.cells.erase(part.cells.begin());
    } else {
      const double n = static_cast<double>(first.count);
      const Eigen::Vector3d m(job_min[0], job_min[1], job_min[2]);
      first.mean = (first.mean * n - m) / (n - 1.0);
      --first.count;
    }
  }
  part.layout.origin = Eigen::Vector3d::Zero();
  return part;
}

/// Distributed: each rank bins its share of the files (world-aligned, or from the job's cloud
/// minimum), the cells are reduced over the ranks; rank 0 gets the outcome (the others an empty
/// one).
GridOutcome buildRanks(const GridOptions& o, const Ranks& ranks) {
  GridOutcome g;
  GridAccumulator local(o.cell_size);
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(o.cell_size);
  grid.setOrigin(GridOrigin::WorldAligned);
  grid.setNumberOfThreads(o.threads != 0 ? o.threads : ranks.threads(0));
  const auto t0 = std::chrono::steady_clock::now();
  double load_s = 0.0;
  const auto [first, last] = ranks.share(o.files.size());
  // The rank's files as one input, as the one-process command does: one build, one part.
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (std::size_t i = first; i < last; ++i) {
    const LoadedCloud loaded = loadTimed(o.files[i]);
    load_s += loaded.seconds;
    *cloud += *loaded.cloud;
  }
  if (o.origin == "cloud-min") {
    // every rank takes part in the all-reduce, with or without points
    std::vector<double> job_min = finiteMinimum(*cloud);
    ranks.minAll(job_min);
    if (!cloud->empty()) local.add(jobMinimumPart(grid, cloud, job_min), cloud->size());
  } else if (!cloud->empty()) {
    grid.setInputCloud(cloud);
    grid.compute();
    local.add({grid.getLayout(), grid.getCells(), grid.getStatistics()}, cloud->size());
  }
  g.load_s = load_s;
  if (o.out.empty() && o.cells.empty()) {  // statistics only: no cells gathered on rank 0
    const GridSummary all = ranks.reduceSummary(local);
    finishSeconds(ranks, g, t0);
    g.input_points = all.input_points;
    g.stats = gridStatisticsOf(all, o.cell_size).stats;
    return g;
  }
  const GridAccumulator all = ranks.reduce(local);
  finishSeconds(ranks, g, t0);
  if (!ranks.isRoot()) return g;
  const GridResult r = all.result();
  g.input_points = all.inputPoints();
  g.stats = r.stats;
  g.cells = r.cells;
  g.means.resize(r.cells.size());  // as OccupancyGrid::filter makes them
  for (std::size_t i = 0; i < r.cells.size(); ++i) {
    g.means[i].x = static_cast<float>(r.cells[i].mean.x());
    g.means[i].y = static_cast<float>(r.cells[i].mean.y());
    g.means[i].z = static_cast<float>(r.cells[i].mean.z());
  }
  g.means.width = static_cast<std::uint32_t>(g.means.size());
  g.means.height = 1;
  g.means.is_dense = true;
  return g;
}

void runGrid(const GridOptions& o, const CLI::App& app) {
  requireDistinctInputs(withRole("input", o.files));
  requireDistinctFiles(withRole("input", o.files), {{"--out", o.out}, {"--cells", o.cells}});
  requireExtension("--out", o.out, {".pcd"}, "a PCD cloud");
  requireExtension("--cells", o.cells, {".csv"}, "CSV");
  refuseIgnored(app, "--pcd-format", !o.out.empty(),
                "without --out: it is the encoding of the PCD written there");
  const Ranks ranks(o.distributed);
  ranks.run([&] {
    const GridOutcome g = o.distributed ? buildRanks(o, ranks) : buildOne(o);
    if (ranks.isRoot()) emitGrid(o, g);
  });
}

}  // namespace

void addGridCommand(CLI::App& app) {
  auto o = std::make_shared<GridOptions>();
  CLI::App* sub = app.add_subcommand("grid", "Occupancy grid: cell counts and means");
  sub->add_option("file", o->files,
                  "Point clouds (.pcd, .ply, .bin, .npy): one input, concatenated")
      ->required();
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
  sub->add_option("--threads", o->threads,
                  "Build threads (0: all hardware threads; with --distributed, the node's "
                  "threads shared among its ranks); the result does not depend on it")
      ->check(countIn(0, 1024))
      ->capture_default_str();
  sub->add_flag("--distributed", o->distributed,
                "Run as MPI ranks (mpirun -np N metricmap grid ...): each rank bins its share of "
                "the files, cells are reduced by tile; the one-process result for either "
                "--origin (cloud-min: the ranks first agree on the input's minimum)");
  addFormatOption(*sub, o->format, {"table", "csv", "json"});
  addPcdFormatOption(*sub, o->pcd_format);
  sub->callback([o, sub] { runGrid(*o, *sub); });
}

}  // namespace metricmap::cli
