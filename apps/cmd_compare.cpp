// metricmap compare FILE... --config ...: the grid-vs-octree study table over files x configs.
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "compare_report.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"
#include "metricmap/octree/grid_octree_study.h"
#include "pcl_peer.h"
#include "study_config.h"

namespace metricmap::cli {
namespace {

struct CompareOptions {
  std::vector<std::string> files;
  std::vector<std::string> configs;
  bool pcl_octree = false;
  std::string format = "table", out, plot;
};

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
  std::vector<StudyRecord> records;
  for (const std::string& f : o.files) {
    const LoadedCloud loaded = loadTimed(f);
    for (const StudyConfig& c : configs) {
      StudyRecord r{f, loaded.cloud->size(), c, {}, loaded.seconds, {}};
      r.figures = gridOctreeFigures(loaded.cloud, c.cell_size, c.min_cell_size, c.max_points);
      if (o.pcl_octree) r.pcl = runPclOctree(loaded.cloud, c.min_cell_size, c.max_points);
      records.push_back(r);
    }
  }
  // The table file and the plot are committed together: a failed plot leaves no table behind.
  const std::string table = renderStudy(records, o.format, o.pcl_octree);
  OutputSet outputs;
  if (!o.out.empty()) writeTextAtomic(outputs.stage(o.out), table);
  if (!o.plot.empty()) {
    const std::string staged = outputs.stage(o.plot);
    try {
      plotStudy(records, o.pcl_octree, staged);
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
