#pragma once
/// \file occupancy_2d_options.h
/// \brief The 2D log-odds occupancy grid's options and output, shared by the commands that
/// build maps from a scan source: --out-occupancy-2d, its image, resolution, band and range.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "metricmap/io/output_set.h"
#include "metricmap/sequence/scan_mapper.h"

namespace metricmap::cli {

struct Occupancy2DOptions {
  std::string out, image = "trinary";
  double resolution = 0.05;
  std::vector<double> band = {-0.5, 0.5};
  std::optional<double> max_range;
};

/// \brief --out-occupancy-2d, --occupancy-2d-image, --occupancy-2d-resolution, --band-2d,
/// --occupancy-2d-max-range.
void addOccupancy2DOptions(CLI::App& app, Occupancy2DOptions& o);
/// \brief Usage checks (exit 2): the band, options without --out-occupancy-2d, the extension.
/// \throws CLI::ValidationError
void checkOccupancy2DOptions(const CLI::App& app, const Occupancy2DOptions& o);
/// \brief The files --out-occupancy-2d writes (the PGM and its YAML), for output identity checks.
RolePaths occupancy2DOutputs(const Occupancy2DOptions& o);
/// \brief The grid's configuration; empty without --out-occupancy-2d.
std::optional<Occupancy2DConfig> occupancy2DConfig(const Occupancy2DOptions& o);
/// \brief Stage the PGM and YAML of the grid in `outputs` and write them; the summary (cells,
/// occupied, free, image size) for the report. Nothing without --out-occupancy-2d.
nlohmann::json writeOccupancy2D(const ScanMapper& maps, const Occupancy2DOptions& o,
                                OutputSet& outputs);

}  // namespace metricmap::cli
