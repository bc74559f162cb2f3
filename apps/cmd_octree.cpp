// metricmap octree FILE --max-points N --min-cell-size S: adaptive octree statistics, leaves.
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "metricmap/octree/adaptive_octree.h"
#include "metricmap/octree/octree_csv.h"
#include "stats_json.h"
#include "table.h"

namespace metricmap::cli {
namespace {

struct OctreeOptions {
  std::string file;
  long long max_points = 0;
  float min_cell_size = 0.0f;
  bool cubic = false;
  std::string out, leaves, format = "table", pcd_format = "binary";
};

void runOctree(const OctreeOptions& o, const CLI::App& app) {
  requireDistinctFiles({{"input", o.file}}, {{"--out", o.out}, {"--leaves", o.leaves}});
  requireExtension("--out", o.out, {".pcd"}, "a PCD cloud");
  requireExtension("--leaves", o.leaves, {".csv"}, "CSV");
  refuseIgnored(app, "--pcd-format", !o.out.empty(),
                "without --out: it is the encoding of the PCD written there");
  const LoadedCloud loaded = loadTimed(o.file);
  const auto& cloud = loaded.cloud;

  const auto t1 = std::chrono::steady_clock::now();
  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(static_cast<std::size_t>(o.max_points));
  octree.setMinCellSize(o.min_cell_size);
  octree.setCubicRoot(o.cubic);
  octree.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ> means;
  octree.filter(means);
  const double octree_s = secondsSince(t1);

  OutputSet outputs;  // committed once the report is printed
  if (!o.out.empty()) savePcdAtomic(outputs.stage(o.out), means, parsePcdFormat(o.pcd_format));
  if (!o.leaves.empty())
    writeTextAtomic(outputs.stage(o.leaves), octreeLeavesCsv(octree.getResult()));

  const OctreeStatistics& s = octree.getStatistics();
  if (o.format == "json") {
    nlohmann::json j = {{"file", o.file},
                        {"points", cloud->size()},
                        {"max_points", o.max_points},
                        {"min_cell_size", o.min_cell_size},
                        {"cubic_root", o.cubic},
                        {"octree", s},
                        {"seconds", {{"load", loaded.seconds}, {"octree", octree_s}}}};
    emit(j.dump(2) + "\n", outputs);
    return;
  }
  Table t({"file", "max_points", "min_cell_size", "points", "total_nodes", "leaf_nodes",
           "internal_nodes", "occupied_leaves", "empty_leaves", "mean_points_per_occupied_leaf",
           "max_depth"});
  t.addRow({o.file, std::to_string(o.max_points), readable(o.min_cell_size),
            std::to_string(s.points), std::to_string(s.total_nodes), std::to_string(s.leaf_nodes),
            std::to_string(s.internal_nodes), std::to_string(s.occupied_leaves),
            std::to_string(s.empty_leaves), fixed(s.mean_points_per_occupied_leaf, 2),
            std::to_string(s.max_depth)});
  emitTable(t, o.format, outputs);
}

}  // namespace

void addOctreeCommand(CLI::App& app) {
  auto o = std::make_shared<OctreeOptions>();
  CLI::App* sub = app.add_subcommand("octree", "Adaptive octree: node counts and leaf means");
  sub->add_option("file", o->file, "Point cloud (.pcd, .ply, .bin, .npy)")->required();
  sub->add_option("--max-points", o->max_points, "Split nodes holding more points than this")
      ->required()
      ->check(kCount);
  sub->add_option("--min-cell-size", o->min_cell_size,
                  "Do not split nodes whose largest edge is <= this (metres)")
      ->required()
      ->check(kFinitePositiveFloat);
  sub->add_flag("--cubic", o->cubic, "Root = cube of the largest extent (default: bounding box)");
  sub->add_option("--out", o->out, "Write the occupied-leaf means as a PCD")->check(kOutputFile);
  sub->add_option("--leaves", o->leaves, "Write one CSV row per leaf (empty ones too)")
      ->check(kOutputFile);
  addFormatOption(*sub, o->format, {"table", "csv", "json"});
  addPcdFormatOption(*sub, o->pcd_format);
  sub->callback([o, sub] { runOctree(*o, *sub); });
}

}  // namespace metricmap::cli
