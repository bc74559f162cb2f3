// metricmap lines FILE: Split & Merge segments of 2D laser scans (CSV, scan-per-line, CARMEN;
// plain, gzip or bzip2).
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/output_set.h"
#include "metricmap/lines/split_and_merge.h"
#include "svg_drawing.h"
#include "table.h"
#include "viz_loader.h"

namespace metricmap::cli {
namespace {

struct LinesOptions {
  std::string file, preset, format = "table", svg, png, steps, purge = "before-merge";
  ScanLineFormat scan_format;
  bool generic = false;
  std::string generic_option;  ///< the first layout option given (refused with --preset)
  long long scan = 0;
  bool all = false;
  // Defaults: the library's (SplitAndMergeParams), angles shown in degrees.
  double distance = SplitAndMergeParams{}.distance_threshold;
  double angle_deg = SplitAndMergeParams{}.angle_threshold * 180.0 / M_PI;
  double min_length = SplitAndMergeParams{}.min_length, max_gap = SplitAndMergeParams{}.max_gap;
  double chi2 = 0.0;  // 0: split on distance; > 0: the chi-square test with this threshold
  long long min_points = static_cast<long long>(SplitAndMergeParams{}.min_points);
  double range_sigma = SplitAndMergeParams{}.range_sigma;
  double bearing_sigma_deg = SplitAndMergeParams{}.bearing_sigma * 180.0 / M_PI;
};

constexpr double kDeg = M_PI / 180.0;

ScanLog readLog(const LinesOptions& o, const CLI::App& app) {
  if (o.generic && !o.preset.empty()) {  // the preset would silently override the option
    throw UsageError(o.generic_option + ": --preset " + o.preset +
                     " sets the whole log layout; give --preset or the layout options, not both");
  }
  const ScanLineFormat& f = o.scan_format;
  if (o.generic && !(f.max_range > f.min_range)) {  // named as given: `1e1`, not `10.000000`
    const auto quoted = [&app](const char* option, double value) {
      const std::string text = givenText(app, option);
      return std::string(option) + " '" + (text.empty() ? plainNumber(value) : text) + "'";
    };
    throw UsageError(quoted("--min-range", f.min_range) + " must be below " +
                     quoted("--max-range", f.max_range) + ": no range would be valid");
  }
  if (o.generic && o.preset.empty()) {
    try {
      validateScanLineFormat(o.scan_format);  // option values: a usage error
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("scan format", e.what());
    }
  }
  const ScanLineFormat mines = urg04lxMinesFormat();
  const ScanLineFormat* layout =
      !o.preset.empty() ? &mines : (o.generic ? &o.scan_format : nullptr);
  ScanLog log = readScanLog(o.file, layout);
  for (const std::string& w : log.warnings) std::cerr << "warning: " << w << "\n";
  return log;
}

SplitAndMergeParams paramsOf(const LinesOptions& o) {
  SplitAndMergeParams p;
  p.distance_threshold = o.distance;
  // Degrees are converted only when given, so the defaults stay the library's bit for bit.
  if (o.angle_deg != LinesOptions{}.angle_deg) p.angle_threshold = o.angle_deg * kDeg;
  p.min_points = static_cast<std::size_t>(o.min_points);
  p.min_length = o.min_length;
  p.max_gap = o.max_gap;
  p.purge_order = o.purge == "after-merge" ? PurgeOrder::AfterMerge : PurgeOrder::BeforeMerge;
  p.chi2_split = o.chi2 > 0.0;
  if (p.chi2_split) p.chi2_threshold = o.chi2;
  p.range_sigma = o.range_sigma;
  if (o.bearing_sigma_deg != LinesOptions{}.bearing_sigma_deg) {
    p.bearing_sigma = o.bearing_sigma_deg * kDeg;
  }
  return p;
}

nlohmann::json segmentJson(const LineSegment& s) {
  return {{"first_index", s.first_index},
          {"last_index", s.last_index},
          {"start", {s.start.x(), s.start.y()}},
          {"end", {s.end.x(), s.end.y()}},
          {"points", s.points},
          {"length", s.length()},
          {"angle", s.angle()},
          {"fit",
           {{"r", s.fit.r},
            {"alpha", s.fit.alpha},
            {"cov", {{s.fit.cov(0, 0), s.fit.cov(0, 1)}, {s.fit.cov(1, 0), s.fit.cov(1, 1)}}}}}};
}

void runLines(const LinesOptions& o, const CLI::App& app) {
  requireDistinctOutputs({{"--png", o.png}, {"--svg", o.svg}, {"--steps", o.steps}});
  requireExtension("--png", o.png, {".png"}, "a PNG picture");
  requireExtension("--svg", o.svg, {".svg"}, "an SVG picture");
  // Options that would change nothing in this run are refused (issue 24, class 6).
  // A piece holds at least one point: --min-points 1 purges no more than 0.
  refuseIgnored(app, "--purge", o.min_points > 1 || o.min_length > 0.0,
                "with --min-points " + std::to_string(o.min_points) +
                    " and --min-length 0: nothing is purged (every segment has a point)");
  refuseIgnored(app, "--purge", o.angle_deg > 0.0,
                "with --angle-threshold-deg 0: there is no merge step to purge before or after");
  const bool sigmas_used = o.chi2 > 0.0 || o.format == "json";
  for (const char* option : {"--range-sigma", "--bearing-sigma-deg"}) {
    refuseIgnored(app, option, sigmas_used,
                  "without --chi2 or --format json: the noise model shapes the chi-square split "
                  "test and the fits' covariances, which only JSON prints");
  }
  const ScanLog log = readLog(o, app);
  const std::size_t n_scans = log.scans.size();
  if (!o.all && static_cast<std::size_t>(o.scan) >= n_scans) {
    throw std::invalid_argument("--scan " + std::to_string(o.scan) + " is out of range: " + o.file +
                                " has " + std::to_string(n_scans) + " scan(s)");
  }
  const std::size_t first = o.all ? 0 : static_cast<std::size_t>(o.scan);
  const std::size_t last = o.all ? n_scans : first + 1;

  SplitAndMerge<pcl::PointXYZ> sam;
  sam.setParams(paramsOf(o));
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

  std::vector<std::vector<LineSegment>> results(clouds.size());
  std::vector<pcl::PointIndices> members;
  double seconds = 0.0;
  for (std::size_t k = 0; k < clouds.size(); ++k) {
    sam.setInputCloud(clouds[k]);
    const auto t0 = std::chrono::steady_clock::now();
    sam.segment(results[k], members);
    seconds += secondsSince(t0);
  }
  if (!o.png.empty())
    drawingModule().write_scan_png(outputs.stage(o.png), *clouds.front(), results.front());
  if (!o.svg.empty()) {
    writeTextAtomic(outputs.stage(o.svg),
                    drawScanSvg(*clouds.front(), results.front(),
                                o.file + " scan " + std::to_string(first) + ": " +
                                    std::to_string(results.front().size()) + " segments"));
  }
  // The report is printed and checked before the drawings are committed (the class 4 rule).
  if (o.format == "json") {
    nlohmann::json scans = nlohmann::json::array();
    for (std::size_t k = 0; k < results.size(); ++k) {
      nlohmann::json segs = nlohmann::json::array();
      for (const LineSegment& s : results[k]) segs.push_back(segmentJson(s));
      scans.push_back(
          {{"scan", first + k}, {"points", log.scans[first + k].validBeams()}, {"segments", segs}});
    }
    const double rate = seconds > 0.0 ? static_cast<double>(results.size()) / seconds : 0.0;
    emit(nlohmann::json({{"file", o.file},
                         {"scans", scans},
                         {"skipped_lines", log.skipped_lines},
                         {"seconds", seconds},
                         {"scans_per_second", rate}})
                 .dump(2) +
             "\n",
         outputs);
    return;
  }
  Table t({"scan", "first_index", "last_index", "points", "length", "angle_deg", "start_x",
           "start_y", "end_x", "end_y", "fit_r", "fit_alpha_deg"});
  for (std::size_t k = 0; k < results.size(); ++k) {
    for (const LineSegment& s : results[k]) {
      t.addRow({std::to_string(first + k), std::to_string(s.first_index),
                std::to_string(s.last_index), std::to_string(s.points), fixed(s.length(), 3),
                fixed(s.angle() / kDeg, 2), fixed(s.start.x(), 3), fixed(s.start.y(), 3),
                fixed(s.end.x(), 3), fixed(s.end.y(), 3), fixed(s.fit.r, 3),
                fixed(s.fit.alpha / kDeg, 2)});
    }
  }
  emitTable(t, o.format, outputs);
}

}  // namespace

void addLinesCommand(CLI::App& app) {
  auto o = std::make_shared<LinesOptions>();
  CLI::App* sub = app.add_subcommand("lines", "Split & Merge line segments of 2D laser scans");
  sub->add_option("file", o->file,
                  "Scan log: .csv (angle,range), one scan per line (--preset or --count), or "
                  "CARMEN (FLASER/ROBOTLASER1: .clf, .log); plain, gzip or bzip2")
      ->required();
  sub->add_option("--preset", o->preset, "Known log layout")
      ->check(CLI::IsMember({"urg04lx-mines"}));
  ScanLineFormat& f = o->scan_format;
  auto generic = [o](const char* name) {
    return [o, name](const std::string&) {
      if (!o->generic) o->generic_option = name;
      o->generic = true;
    };
  };
  sub->add_option("--skip-tokens", f.skip_tokens, "Tokens before the ranges")
      ->check(kCount)
      ->each(generic("--skip-tokens"));
  sub->add_option("--count", f.count, "Ranges per scan")->check(kCount)->each(generic("--count"));
  sub->add_option("--angle-min-deg", f.angle_min_deg, "Angle of beam 0")
      ->check(kFinite)
      ->each(generic("--angle-min-deg"));
  sub->add_option("--angle-increment-deg", f.angle_increment_deg, "Angle between beams")
      ->check(kFinite)
      ->each(generic("--angle-increment-deg"));
  sub->add_option("--range-scale", f.range_scale, "Raw range x scale = metres")
      ->check(kFinitePositive)
      ->each(generic("--range-scale"));
  sub->add_option("--min-range", f.min_range, "Smaller ranges (m) are invalid")
      ->check(kFiniteNonNegative)
      ->each(generic("--min-range"));
  sub->add_option("--max-range", f.max_range, "Larger ranges (m) are invalid")
      ->check(kFinite)
      ->each(generic("--max-range"));
  auto* scan = sub->add_option("--scan", o->scan, "Scan to segment (0-based)")->check(kCount);
  sub->add_flag("--all", o->all, "Segment every scan")->excludes(scan);
  sub->add_option("--distance-threshold", o->distance, "d_th: split distance, metres")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_option("--angle-threshold-deg", o->angle_deg, "a_th: merge angle, degrees (0: no merge)")
      ->check(finiteIn(0.0, 180.0))
      ->capture_default_str();
  sub->add_option("--min-points", o->min_points, "Purge segments with fewer points (0: off)")
      ->check(kCount)
      ->capture_default_str();
  sub->add_option("--min-length", o->min_length, "Purge shorter segments, metres (0: off)")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--max-gap", o->max_gap, "Split where neighbours are further apart (0: off)")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--purge", o->purge, "When purge runs")
      ->check(CLI::IsMember({"before-merge", "after-merge"}))
      ->capture_default_str();
  sub->add_option("--chi2", o->chi2,
                  "Split on d^2/var(d) > this (chi-square, 1 dof) instead of --distance-threshold")
      ->check(kFinitePositive);
  sub->add_option("--range-sigma", o->range_sigma, "Range noise, metres")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--bearing-sigma-deg", o->bearing_sigma_deg, "Bearing noise, degrees")
      ->check(finiteIn(0.0, 180.0))
      ->capture_default_str();
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
