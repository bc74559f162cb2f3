#pragma once
/// \file cli_common.h
/// \brief Shared pieces of the `metricmap` subcommands: validators, loading, output formats.

#include <chrono>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <CLI/CLI.hpp>

#include "metricmap/io/load_report.h"

namespace metricmap::cli {

/// \brief A finite number > 0 (CLI11's PositiveNumber lets NaN through).
extern const CLI::Validator kFinitePositive;

/// \brief A whole number >= 0 written in decimal digits.
extern const CLI::Validator kCount;

/// \brief Seconds since `start`.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// \brief Load a cloud, printing the reader's warnings to stderr.
LoadReport loadWithWarnings(const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud);

/// \brief Print to stdout, or write atomically to `path` when it is not empty.
void emit(const std::string& text, const std::string& path);

/// \brief Adds --pcd-format with its check; the value lands in `format`.
void addPcdFormatOption(CLI::App& app, std::string& format);

}  // namespace metricmap::cli
