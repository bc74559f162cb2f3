#pragma once
/// \file localize_report.h
/// \brief The report of `metricmap localize`: JSON (with every scan's status and score) or a few
/// lines of text.

#include <string>

#include "metricmap/io/output_set.h"
#include "metricmap/localization/localize_2d_run.h"
#include "metricmap/localization/localize_3d_run.h"

namespace metricmap::cli {

/// \brief Seconds of a run beyond the localiser's own (Localizer2DStats).
struct LocalizeTimes {
  double map = 0.0, write = 0.0, total = 0.0;
  double log = 0.0;  ///< the span of the scans' stamps
};

/// \brief Print the report of `run` over `input` in `map` (`format` json or table), then commit
/// `outputs` (emit's rule). `frames` are the source's indices of the scans.
void emitLocalizeReport(const std::string& input, const std::string& map,
                        const std::vector<std::size_t>& frames, const Localize2DRun& run,
                        const LocalizeTimes& times, const std::string& format, OutputSet& outputs);

/// \brief The same for a 3D run (localize_3d_report.cpp).
void emitLocalizeReport(const std::string& input, const std::string& map,
                        const std::vector<std::size_t>& frames, const Localize3DRun& run,
                        const LocalizeTimes& times, const std::string& format, OutputSet& outputs);

}  // namespace metricmap::cli
