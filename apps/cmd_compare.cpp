// metricmap compare FILE... --config ...: the grid-vs-octree study table over files x configs.
#include <memory>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "metricmap/octree/adaptive_octree.h"
#include "pcl_peer.h"
#include "stats_json.h"
#include "study_config.h"
#include "table.h"
#include "viz_loader.h"

namespace metricmap::cli {
namespace {

struct CompareOptions {
  std::vector<std::string> files;
  std::vector<std::string> configs;
  bool pcl_octree = false;
  std::string format = "table", out, plot;
};

struct Record {
  std::string file;
  std::size_t points = 0;
  StudyConfig config;
  GridStatistics grid;
  OctreeStatistics octree;
  double load_s = 0, grid_s = 0, octree_s = 0;
  PclOctreeFigures pcl;
};

Record study(const std::string& file, const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
             const StudyConfig& c, bool with_pcl) {
  Record r;
  r.file = file;
  r.points = cloud->size();
  r.config = c;
  auto t = std::chrono::steady_clock::now();
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(c.cell_size);
  grid.setInputCloud(cloud);
  grid.compute();
  r.grid = grid.getStatistics();
  r.grid_s = secondsSince(t);

  t = std::chrono::steady_clock::now();
  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(c.max_points);
  octree.setMinCellSize(c.min_cell_size);
  octree.setInputCloud(cloud);
  octree.compute();
  r.octree = octree.getStatistics();
  r.octree_s = secondsSince(t);
  if (with_pcl) r.pcl = runPclOctree(cloud, c.min_cell_size, c.max_points);
  return r;
}

nlohmann::json toJson(const Record& r, bool with_pcl) {
  nlohmann::json j = {
      {"file", r.file},
      {"points", r.points},
      {"config",
       {{"cell_size", r.config.cell_size},
        {"min_cell_size", r.config.min_cell_size},
        {"max_points", r.config.max_points}}},
      {"grid", r.grid},
      {"octree", r.octree},
      {"seconds", {{"load", r.load_s}, {"grid", r.grid_s}, {"octree", r.octree_s}}}};
  if (with_pcl) {
    j["pcl_octree"] = {
        {"leaves", r.pcl.leaves}, {"depth", r.pcl.depth}, {"seconds", r.pcl.seconds}};
  }
  return j;
}

std::string render(const std::vector<Record>& records, const CompareOptions& o) {
  if (o.format == "json") {
    nlohmann::json a = nlohmann::json::array();
    for (const Record& r : records) a.push_back(toJson(r, o.pcl_octree));
    return a.dump(2) + "\n";
  }
  std::vector<std::string> header = {"file",          "cell_size",       "min_cell_size",
                                     "max_points",    "grid_total",      "grid_occupied",
                                     "grid_empty",    "grid_mean",       "octree_nodes",
                                     "octree_leaves", "octree_internal", "octree_occupied",
                                     "octree_empty",  "octree_mean",     "octree_depth"};
  if (o.pcl_octree) {
    header.insert(header.end(), {"pcl_leaves", "pcl_depth"});
  }
  Table t(header);
  const bool csv = o.format == "csv";
  for (const Record& r : records) {
    std::vector<std::string> row = {r.file,
                                    fixed(r.config.cell_size, csv ? 6 : 2),
                                    fixed(r.config.min_cell_size, csv ? 6 : 2),
                                    std::to_string(r.config.max_points),
                                    std::to_string(r.grid.total_cells),
                                    std::to_string(r.grid.occupied_cells),
                                    std::to_string(r.grid.empty_cells),
                                    fixed(r.grid.mean_points_per_occupied_cell, csv ? 6 : 2),
                                    std::to_string(r.octree.total_nodes),
                                    std::to_string(r.octree.leaf_nodes),
                                    std::to_string(r.octree.internal_nodes),
                                    std::to_string(r.octree.occupied_leaves),
                                    std::to_string(r.octree.empty_leaves),
                                    fixed(r.octree.mean_points_per_occupied_leaf, csv ? 6 : 2),
                                    std::to_string(r.octree.max_depth)};
    if (o.pcl_octree) {
      row.insert(row.end(), {std::to_string(r.pcl.leaves), std::to_string(r.pcl.depth)});
    }
    t.addRow(row);
  }
  const TableStyle style =
      csv ? TableStyle::Csv : (o.format == "markdown" ? TableStyle::Markdown : TableStyle::Aligned);
  return t.render(style);
}

void plot(const std::vector<Record>& records, const CompareOptions& o, const std::string& path) {
  std::vector<std::string> categories;
  viz::PlotPanel total{"cells / nodes in all", false, {}},
      occupied{"occupied cells / leaves", false, {}}, empty{"empty cells / leaves", false, {}},
      mean{"mean points per occupied cell / leaf", false, {}};
  std::vector<double> g_total, o_total, g_occ, o_occ, g_empty, o_empty, g_mean, o_mean, p_leaves;
  for (const Record& r : records) {
    std::string name = r.file.substr(r.file.find_last_of('/') + 1);
    name = name.substr(0, name.find('.')) + " " + fixed(r.config.cell_size, 1) + "/" +
           fixed(r.config.min_cell_size, 1) + "/" + std::to_string(r.config.max_points);
    categories.push_back(name);
    g_total.push_back(static_cast<double>(r.grid.total_cells));
    o_total.push_back(static_cast<double>(r.octree.total_nodes));
    g_occ.push_back(static_cast<double>(r.grid.occupied_cells));
    o_occ.push_back(static_cast<double>(r.octree.occupied_leaves));
    g_empty.push_back(static_cast<double>(r.grid.empty_cells));
    o_empty.push_back(static_cast<double>(r.octree.empty_leaves));
    g_mean.push_back(r.grid.mean_points_per_occupied_cell);
    o_mean.push_back(r.octree.mean_points_per_occupied_leaf);
    p_leaves.push_back(static_cast<double>(r.pcl.leaves));
  }
  total.series = {{"grid", g_total}, {"octree", o_total}};
  occupied.series = {{"grid", g_occ}, {"octree", o_occ}};
  if (o.pcl_octree) occupied.series.push_back({"pcl::octree leaves", p_leaves});
  empty.series = {{"grid", g_empty}, {"octree", o_empty}};
  mean.series = {{"grid", g_mean}, {"octree", o_mean}};
  drawingModule().write_study_plot(path, categories, {total, occupied, empty, mean});
}

void runCompare(const CompareOptions& o) {
  requireDistinctInputs(withRole("input", o.files));
  requireDistinctFiles(withRole("input", o.files), {{"--out", o.out}, {"--plot", o.plot}});
  if (o.format == "csv") {
    requireExtension("--out", o.out, {".csv"}, "CSV, as --format csv");
  } else if (o.format == "json") {
    requireExtension("--out", o.out, {".json"}, "JSON, as --format json");
  } else if (o.format == "markdown") {
    requireExtension("--out", o.out, {".md", ".txt"}, "Markdown, as --format markdown");
  } else {
    requireExtension("--out", o.out, {".txt"}, "an aligned text table, as --format " + o.format);
  }
  requireExtension("--plot", o.plot, {".png", ".svg"}, "a PNG or SVG picture");
  std::vector<StudyConfig> configs;
  for (const std::string& text : o.configs) {
    StudyConfig c;
    parseStudyConfig(text, c);  // already validated by the option's check
    configs.push_back(c);
  }
  if (configs.empty()) configs = studyConfigs();
  std::vector<Record> records;
  for (const std::string& f : o.files) {
    const LoadedCloud loaded = loadTimed(f);
    for (const StudyConfig& c : configs) {
      records.push_back(study(f, loaded.cloud, c, o.pcl_octree));
      records.back().load_s = loaded.seconds;
    }
  }
  // The table file and the plot are committed together: a failed plot leaves no table behind.
  const std::string table = render(records, o);
  OutputSet outputs;
  if (!o.out.empty()) writeTextAtomic(outputs.stage(o.out), table);
  if (!o.plot.empty()) {
    const std::string staged = outputs.stage(o.plot);
    try {
      plot(records, o, staged);
    } catch (const std::runtime_error& e) {
      // the drawing module names the path it was given: show the destination, never the
      // temporary it is staged as
      std::string what = e.what();
      for (std::size_t at; (at = what.find(staged)) != std::string::npos;)
        what.replace(at, staged.size(), o.plot);
      throw std::runtime_error(what);
    }
  }
  emit(o.out.empty() ? table : std::string(), outputs);  // the report first, then the files
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare", "Grid vs octree statistics over files x configurations (the study's table)");
  sub->add_option("files", o->files, "Point clouds (.pcd, .ply, .bin, .npy)")->required();
  sub->add_option("--config", o->configs,
                  "cell_size=S,min_cell_size=M,max_points=N; repeatable. "
                  "Default: the study's 1/1/100, 0.5/0.5/100, 2/1/200")
      ->check(CLI::Validator(
          [](std::string& s) {
            StudyConfig c;
            return parseStudyConfig(s, c);
          },
          "CONFIG"));
  sub->add_flag("--pcl-octree", o->pcl_octree,
                "Also run pcl::octree::OctreePointCloudPointVector (dynamic depth) on each job");
  addFormatOption(*sub, o->format, {"table", "markdown", "csv", "json"});
  sub->add_option("--out", o->out, "Write the output to this file instead of stdout")
      ->check(kOutputFile);
  sub->add_option("--plot", o->plot,
                  "Also draw the figures as grouped bars (.png or .svg; needs X: xvfb-run -a)");
  sub->callback([o] { runCompare(*o); });
}

}  // namespace metricmap::cli
