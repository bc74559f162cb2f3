#pragma once
/// \file scan_log_options.h
/// \brief --preset and the scan-per-line layout options (--skip-tokens, --count, ...) of a 2D
/// scan log, and reading the log they describe (lines).

#include <string>

#include <CLI/CLI.hpp>

#include "metricmap/io/laser_scan.h"

namespace metricmap::cli {

struct ScanLogOptions {
  std::string preset;
  ScanLineFormat scan_format;
  bool generic = false;        ///< a layout option was given
  std::string generic_option;  ///< the first layout option given (refused with --preset)
};

/// \brief Adds --preset and the layout options.
void addScanLogOptions(CLI::App& app, ScanLogOptions& o);

/// \brief The log `file` in the layout the options give (a preset, the layout options, or as
/// detected), its warnings printed to stderr. Usage errors (exit 2): --preset with a layout
/// option, --min-range not below --max-range, a layout the reader refuses.
ScanLog readScanLogOptions(const std::string& file, const ScanLogOptions& o, const CLI::App& app);

}  // namespace metricmap::cli
