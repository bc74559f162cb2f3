#pragma once
/// \file lines_report.h
/// \brief The report of `metricmap lines`: JSON, or a table of every segment.

#include <cstddef>
#include <string>
#include <vector>

#include "metricmap/io/laser_scan.h"
#include "metricmap/lines/line_segment.h"

namespace metricmap::cli {

class Table;

/// \brief The segments of scans first, first + 1, ... of `log` (read from `file`) as JSON.
std::string linesJson(const std::string& file, const ScanLog& log, std::size_t first,
                      const std::vector<std::vector<LineSegment>>& segments, double seconds);

/// \brief One row per segment of scans first, first + 1, ...
Table linesTable(std::size_t first, const std::vector<std::vector<LineSegment>>& segments);

}  // namespace metricmap::cli
