#pragma once
/// \file cli_common.h
/// \brief Shared pieces of the `metricmap` subcommands: validators, loading, output formats.

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <CLI/CLI.hpp>

#include "metricmap/io/load_report.h"

namespace metricmap::cli {

/// \brief A usage error found after parsing (a bad combination or value of options): exit 2.
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// \brief Any finite decimal number (metricmap::parseFiniteDouble: no hex, inf, nan, garbage).
extern const CLI::Validator kFinite;

/// \brief A finite number > 0 (CLI11's PositiveNumber lets NaN through).
extern const CLI::Validator kFinitePositive;

/// \brief A finite number > 0 that a float holds as a normal number (the grid and octree sizes
/// are float: 1e308 would become inf, 1e-300 zero).
extern const CLI::Validator kFinitePositiveFloat;

/// \brief A finite number >= 0.
extern const CLI::Validator kFiniteNonNegative;

/// \brief A whole number >= 0 written in decimal digits.
extern const CLI::Validator kCount;

/// \brief An output file name: not empty (`--out ''` would write nothing and succeed).
extern const CLI::Validator kOutputFile;

/// \brief Usage error (exit 2) when two of the outputs name the same file; `outputs` holds
/// (option, path) pairs, empty paths skipped. Paths are compared after weakly_canonical, so
/// "a.bt" and "./a.bt" are the same file.
void requireDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs);

/// \brief Seconds since `start`.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// \brief Load a cloud, printing the reader's warnings to stderr.
LoadReport loadWithWarnings(const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud);

/// \brief A cloud loaded by loadWithWarnings, with how long it took.
struct LoadedCloud {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  LoadReport report;
  double seconds = 0.0;
};
LoadedCloud loadTimed(const std::string& path);

/// \brief Adds --format restricted to `choices` (the first is the default shown).
void addFormatOption(CLI::App& app, std::string& format, const std::vector<std::string>& choices);

/// \brief Print a table in the style --format names: csv, markdown, anything else aligned.
void emitTable(const class Table& table, const std::string& format, const std::string& path = "");

/// \brief Print to stdout, or write atomically to `path` when it is not empty.
void emit(const std::string& text, const std::string& path);

/// \brief Adds --pcd-format with its check; the value lands in `format`.
void addPcdFormatOption(CLI::App& app, std::string& format);

}  // namespace metricmap::cli
