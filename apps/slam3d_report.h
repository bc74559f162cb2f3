#pragma once
/// \file slam3d_report.h
/// \brief The report of `metricmap slam3d`: JSON or a few lines of text.

#include <string>

#include "metricmap/io/output_set.h"

namespace metricmap {
struct Slam3DRun;
}

namespace metricmap::cli {

/// \brief Seconds of a run beyond the SLAM's own, and the peak memory.
struct Slam3DTimes {
  double maps = 0.0, write = 0.0, total = 0.0;
  double span = 0.0;  ///< the span of the scans' stamps (0: no stamps)
  double peak_mib = 0.0;
};

/// \brief Print the report of `run` over `input` (`format` json or table), then commit
/// `outputs` (emit's rule).
void emitSlam3DReport(const std::string& input, const Slam3DRun& run, const Slam3DTimes& times,
                      const std::string& format, OutputSet& outputs);

}  // namespace metricmap::cli
