// metricmap lines FILE: Split & Merge segments of 2D laser scans (CSV, scan-per-line, CARMEN;
// plain, gzip or bzip2).
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <sstream>

#include "cli_common.h"
#include "commands.h"
#include "lines_report.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/output_set.h"
#include "metricmap/lines/segment_clouds.h"
#include "scan_log_options.h"
#include "split_and_merge_options.h"
#include "svg_drawing.h"
#include "table.h"
#include "viz_loader.h"

namespace metricmap::cli {
namespace {

struct LinesOptions {
  std::string file, format = "table", svg, png, steps;
  ScanLogOptions log;
  long long scan = 0;
  bool all = false;
  SplitAndMergeOptions sam;
};

void runLines(const LinesOptions& o, const CLI::App& app) {
  requireDistinctOutputs({{"--png", o.png}, {"--svg", o.svg}, {"--steps", o.steps}});
  requireExtension("--png", o.png, {".png"}, "a PNG picture");
  requireExtension("--svg", o.svg, {".svg"}, "an SVG picture");
  checkSplitAndMergeOptions(app, o.sam, o.format == "json");
  const ScanLog log = readScanLogOptions(o.file, o.log, app);
  const std::size_t n_scans = log.scans.size();
  if (!o.all && static_cast<std::size_t>(o.scan) >= n_scans) {
    throw std::invalid_argument("--scan " + std::to_string(o.scan) + " is out of range: " + o.file +
                                " has " + std::to_string(n_scans) + " scan(s)");
  }
  const std::size_t first = o.all ? 0 : static_cast<std::size_t>(o.scan);
  const std::size_t last = o.all ? n_scans : first + 1;

  SplitAndMerge<pcl::PointXYZ> sam;
  sam.setParams(splitAndMergeParams(o.sam));
  std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> clouds;
  for (std::size_t k = first; k < last; ++k) {
    clouds.push_back(std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(scanToCloud(log.scans[k])));
  }
  int step_no = 0;
  OutputSet outputs;  // the drawings and the steps are committed together, after segmentation
  if (!o.steps.empty()) {
    const std::string steps_dir = outputs.stageDirectory(o.steps);
    sam.setStepCallback(
        [&, steps_dir](const std::string& what, const std::vector<LineSegment>& segs) {
          std::ostringstream name;
          name << steps_dir << "/step_" << std::setw(4) << std::setfill('0') << ++step_no << "_"
               << what << ".svg";
          writeTextAtomic(name.str(),
                          drawScanSvg(*clouds.front(), segs,
                                      "step " + std::to_string(step_no) + ": " + what + ", " +
                                          std::to_string(segs.size()) + " segments"));
        });
  }

  const SegmentedClouds segmented = segmentClouds(sam, clouds);
  const auto& results = segmented.segments;
  if (!o.png.empty())
    drawingModule().write_scan_png(outputs.stage(o.png), *clouds.front(), results.front());
  if (!o.svg.empty()) {
    writeTextAtomic(outputs.stage(o.svg),
                    drawScanSvg(*clouds.front(), results.front(),
                                o.file + " scan " + std::to_string(first) + ": " +
                                    std::to_string(results.front().size()) + " segments"));
  }
  // The report is printed and checked before the drawings are committed (the class 4 rule).
  if (o.format == "json")
    return emit(linesJson(o.file, log, first, results, segmented.seconds), outputs);
  emitTable(linesTable(first, results), o.format, outputs);
}

}  // namespace

void addLinesCommand(CLI::App& app) {
  auto o = std::make_shared<LinesOptions>();
  CLI::App* sub = app.add_subcommand("lines", "Split & Merge line segments of 2D laser scans");
  sub->add_option("file", o->file,
                  "Scan log: .csv (angle,range), one scan per line (--preset or --count), or "
                  "CARMEN (FLASER/ROBOTLASER1: .clf, .log); plain, gzip or bzip2")
      ->required();
  addScanLogOptions(*sub, o->log);
  auto* scan = sub->add_option("--scan", o->scan, "Scan to segment (0-based)")->check(kCount);
  sub->add_flag("--all", o->all, "Segment every scan")->excludes(scan);
  addSplitAndMergeOptions(*sub, o->sam);
  addFormatOption(*sub, o->format, {"table", "csv", "json"});
  sub->add_option("--svg", o->svg, "Draw the scan and its segments (not with --all)")
      ->check(kOutputFile)
      ->excludes("--all");
  sub->add_option("--png", o->png, "Draw the scan and its segments as PNG (not with --all)")
      ->check(kOutputFile)
      ->excludes("--all");
  sub->add_option("--steps", o->steps, "Write one SVG per split/merge/purge step to DIR")
      ->check(kOutputFile)
      ->excludes("--all");
  sub->callback([o, sub] { runLines(*o, *sub); });
}

}  // namespace metricmap::cli
