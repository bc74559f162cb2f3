#pragma once
/// \file slam2d_report.h
/// \brief The report of `metricmap slam2d`: JSON or a few lines of text.

#include <string>

#include "metricmap/io/output_set.h"

namespace metricmap {
class Slam2D;
}

namespace metricmap::cli {

/// \brief Seconds of a run beyond the SLAM's own (Slam2DStats).
struct Slam2DTimes {
  double read = 0.0, write = 0.0, total = 0.0;
  double log = 0.0;  ///< the span of the log's stamps
};

/// \brief Print the report of the finished `slam` run over `input` (`format` json or table),
/// then commit `outputs` (emit's rule).
void emitSlam2DReport(const std::string& input, const Slam2D& slam, const Slam2DTimes& times,
                      const std::string& format, OutputSet& outputs);

}  // namespace metricmap::cli
