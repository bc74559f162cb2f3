// metricmap grid FILE... --cell-size S: occupancy grid statistics, cell means, per-cell CSV.
// Several files are one input (concatenated). With --distributed (under mpirun) each rank bins
// its share of the files and the cells are reduced over MPI (ranks.h); with the default
// --origin cloud-min the ranks first agree on the minimum of the whole input (one all-reduce).
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "concatenated_cloud.h"
#include "grid_report.h"
#include "metricmap/grid/cell_means.h"
#include "metricmap/grid/grid_accumulator.h"
#include "metricmap/grid/grid_csv.h"
#include "metricmap/grid/grid_part.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "ranks.h"

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

/// One process: the files concatenated, one build (any origin).
GridOutcome buildOne(const GridOptions& o) {
  GridOutcome g;
  const LoadedCloud loaded = loadConcatenated(o.files, 0, o.files.size());
  g.load_s = loaded.seconds;
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
  const auto [first, last] = ranks.share(o.files.size());
  // The rank's files as one input, as the one-process command does: one build, one part.
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  const LoadedCloud loaded = loadConcatenated(o.files, first, last);
  *cloud += *loaded.cloud;
  g.load_s = loaded.seconds;
  std::vector<double> job_min;
  if (o.origin == "cloud-min") {  // every rank takes part in the all-reduce, with or without points
    job_min = finiteMinimum(*cloud);
    ranks.minAll(job_min);
  }
  if (!cloud->empty())
    local.add(gridPart(grid, cloud, o.origin == "cloud-min" ? &job_min : nullptr), cloud->size());
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
  g.means = cellMeans(r.cells);  // as OccupancyGrid::filter makes them
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
    if (!ranks.isRoot()) return;
    OutputSet outputs;  // committed once the report is printed
    if (!o.out.empty()) savePcdAtomic(outputs.stage(o.out), g.means, parsePcdFormat(o.pcd_format));
    if (!o.cells.empty()) writeTextAtomic(outputs.stage(o.cells), gridCellsCsv(g.cells));
    emitGridReport(o.files, o.cell_size, o.origin, g, o.format, outputs);
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
