#include "lines_report.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "table.h"

namespace metricmap::cli {
namespace {

constexpr double kDeg = M_PI / 180.0;

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

}  // namespace

std::string linesJson(const std::string& file, const ScanLog& log, std::size_t first,
                      const std::vector<std::vector<LineSegment>>& segments, double seconds) {
  nlohmann::json scans = nlohmann::json::array();
  for (std::size_t k = 0; k < segments.size(); ++k) {
    nlohmann::json segs = nlohmann::json::array();
    for (const LineSegment& s : segments[k]) segs.push_back(segmentJson(s));
    scans.push_back(
        {{"scan", first + k}, {"points", log.scans[first + k].validBeams()}, {"segments", segs}});
  }
  const double rate = seconds > 0.0 ? static_cast<double>(segments.size()) / seconds : 0.0;
  return nlohmann::json({{"file", file},
                         {"scans", scans},
                         {"skipped_lines", log.skipped_lines},
                         {"seconds", seconds},
                         {"scans_per_second", rate}})
             .dump(2) +
         "\n";
}

Table linesTable(std::size_t first, const std::vector<std::vector<LineSegment>>& segments) {
  Table t({"scan", "first_index", "last_index", "points", "length", "angle_deg", "start_x",
           "start_y", "end_x", "end_y", "fit_r", "fit_alpha_deg"});
  for (std::size_t k = 0; k < segments.size(); ++k) {
    for (const LineSegment& s : segments[k]) {
      t.addRow({std::to_string(first + k), std::to_string(s.first_index),
                std::to_string(s.last_index), std::to_string(s.points), fixed(s.length(), 3),
                fixed(s.angle() / kDeg, 2), fixed(s.start.x(), 3), fixed(s.start.y(), 3),
                fixed(s.end.x(), 3), fixed(s.end.y(), 3), fixed(s.fit.r, 3),
                fixed(s.fit.alpha / kDeg, 2)});
    }
  }
  return t;
}

}  // namespace metricmap::cli
