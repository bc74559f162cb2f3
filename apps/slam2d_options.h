#pragma once
/// \file slam2d_options.h
/// \brief The SLAM options of `metricmap slam2d`: the common parameters by their own options,
/// any parameter by `--set NAME=VALUE` (slam/slam_2d_parameters.h), --no-loop-closure.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "metricmap/slam/slam_2d_config.h"

namespace metricmap::cli {

struct Slam2DOptionValues {
  Slam2DConfig config;
  std::vector<std::string> set;  ///< NAME=VALUE
  bool no_loops = false;
};

/// \brief Adds the options.
void addSlam2DOptions(CLI::App& app, Slam2DOptionValues& o);

/// \brief After parsing: loop options refused with --no-loop-closure; --set applied to the
/// configuration (each name once, not also given by its own option, no loop parameter with
/// --no-loop-closure; the whole configuration valid); --max-range above the minimum range.
/// \throws UsageError (exit 2)
void applySlam2DOptions(const CLI::App& app, Slam2DOptionValues& o);

}  // namespace metricmap::cli
