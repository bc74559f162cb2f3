#include "compare_report.h"

#include <nlohmann/json.hpp>

#include "stats_json.h"
#include "table.h"
#include "viz_loader.h"

namespace metricmap::cli {
namespace {

nlohmann::json toJson(const StudyRecord& r, bool with_pcl) {
  nlohmann::json j = {
      {"file", r.file},
      {"points", r.points},
      {"config",
       {{"cell_size", r.config.cell_size},
        {"min_cell_size", r.config.min_cell_size},
        {"max_points", r.config.max_points}}},
      {"grid", r.figures.grid},
      {"octree", r.figures.octree},
      {"seconds",
       {{"load", r.load_s}, {"grid", r.figures.grid_s}, {"octree", r.figures.octree_s}}}};
  if (with_pcl) {
    j["pcl_octree"] = {
        {"leaves", r.pcl.leaves}, {"depth", r.pcl.depth}, {"seconds", r.pcl.seconds}};
  }
  return j;
}

}  // namespace

std::string renderStudy(const std::vector<StudyRecord>& records, const std::string& format,
                        bool with_pcl) {
  if (format == "json") {
    nlohmann::json a = nlohmann::json::array();
    for (const StudyRecord& r : records) a.push_back(toJson(r, with_pcl));
    return a.dump(2) + "\n";
  }
  std::vector<std::string> header = {"file",          "cell_size",       "min_cell_size",
                                     "max_points",    "grid_total",      "grid_occupied",
                                     "grid_empty",    "grid_mean",       "octree_nodes",
                                     "octree_leaves", "octree_internal", "octree_occupied",
                                     "octree_empty",  "octree_mean",     "octree_depth"};
  if (with_pcl) {
    header.insert(header.end(), {"pcl_leaves", "pcl_depth"});
  }
  Table t(header);
  const bool csv = format == "csv";
  for (const StudyRecord& r : records) {
    std::vector<std::string> row = {
        r.file,
        fixed(r.config.cell_size, csv ? 6 : 2),
        fixed(r.config.min_cell_size, csv ? 6 : 2),
        std::to_string(r.config.max_points),
        std::to_string(r.figures.grid.total_cells),
        std::to_string(r.figures.grid.occupied_cells),
        std::to_string(r.figures.grid.empty_cells),
        fixed(r.figures.grid.mean_points_per_occupied_cell, csv ? 6 : 2),
        std::to_string(r.figures.octree.total_nodes),
        std::to_string(r.figures.octree.leaf_nodes),
        std::to_string(r.figures.octree.internal_nodes),
        std::to_string(r.figures.octree.occupied_leaves),
        std::to_string(r.figures.octree.empty_leaves),
        fixed(r.figures.octree.mean_points_per_occupied_leaf, csv ? 6 : 2),
        std::to_string(r.figures.octree.max_depth)};
    if (with_pcl) {
      row.insert(row.end(), {std::to_string(r.pcl.leaves), std::to_string(r.pcl.depth)});
    }
    t.addRow(row);
  }
  const TableStyle style =
      csv ? TableStyle::Csv : (format == "markdown" ? TableStyle::Markdown : TableStyle::Aligned);
  return t.render(style);
}

void plotStudy(const std::vector<StudyRecord>& records, bool with_pcl, const std::string& path) {
  std::vector<std::string> categories;
  viz::PlotPanel total{"cells / nodes in all", false, {}},
      occupied{"occupied cells / leaves", false, {}}, empty{"empty cells / leaves", false, {}},
      mean{"mean points per occupied cell / leaf", false, {}};
  std::vector<double> g_total, o_total, g_occ, o_occ, g_empty, o_empty, g_mean, o_mean, p_leaves;
  for (const StudyRecord& r : records) {
    std::string name = r.file.substr(r.file.find_last_of('/') + 1);
    name = name.substr(0, name.find('.')) + " " + fixed(r.config.cell_size, 1) + "/" +
           fixed(r.config.min_cell_size, 1) + "/" + std::to_string(r.config.max_points);
    categories.push_back(name);
    g_total.push_back(static_cast<double>(r.figures.grid.total_cells));
    o_total.push_back(static_cast<double>(r.figures.octree.total_nodes));
    g_occ.push_back(static_cast<double>(r.figures.grid.occupied_cells));
    o_occ.push_back(static_cast<double>(r.figures.octree.occupied_leaves));
    g_empty.push_back(static_cast<double>(r.figures.grid.empty_cells));
    o_empty.push_back(static_cast<double>(r.figures.octree.empty_leaves));
    g_mean.push_back(r.figures.grid.mean_points_per_occupied_cell);
    o_mean.push_back(r.figures.octree.mean_points_per_occupied_leaf);
    p_leaves.push_back(static_cast<double>(r.pcl.leaves));
  }
  total.series = {{"grid", g_total}, {"octree", o_total}};
  occupied.series = {{"grid", g_occ}, {"octree", o_occ}};
  if (with_pcl) occupied.series.push_back({"pcl::octree leaves", p_leaves});
  empty.series = {{"grid", g_empty}, {"octree", o_empty}};
  mean.series = {{"grid", g_mean}, {"octree", o_mean}};
  drawingModule().write_study_plot(path, categories, {total, occupied, empty, mean});
}

}  // namespace metricmap::cli
