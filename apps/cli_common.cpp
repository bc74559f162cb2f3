#include "cli_common.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

#include "metricmap/common/parse_number.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "table.h"

namespace metricmap::cli {

namespace {

/// The value through the library's checked parser; "" or the reason it is refused.
std::string checkedDouble(const std::string& s, double& v) {
  try {
    v = parseFiniteDouble(s, "value");
  } catch (const std::invalid_argument&) {
    return "'" + quoteForMessage(s) + "' is not a finite decimal number";
  }
  return std::string();
}

}  // namespace

const CLI::Validator kFinite(
    [](std::string& s) -> std::string {
      double v = 0.0;
      return checkedDouble(s, v);
    },
    "FINITE");

const CLI::Validator kFinitePositive(
    [](std::string& s) -> std::string {
      double v = 0.0;
      std::string why = checkedDouble(s, v);
      if (why.empty() && !(v > 0.0)) why = "must be a finite number > 0, got " + s;
      return why;
    },
    "POSITIVE");

const CLI::Validator kFinitePositiveFloat(
    [](std::string& s) -> std::string {
      double v = 0.0;
      std::string why = checkedDouble(s, v);
      if (why.empty() && !(v > 0.0))
        why = "must be a finite number > 0, got '" + quoteForMessage(s) + "'";
      if (why.empty() &&
          !(v >= std::numeric_limits<float>::min() && v <= std::numeric_limits<float>::max())) {
        why = "'" + quoteForMessage(s) +
              "' is outside the single-precision range (1.2e-38 to 3.4e38)";
      }
      return why;
    },
    "POSITIVE");

const CLI::Validator kFiniteNonNegative(
    [](std::string& s) -> std::string {
      double v = 0.0;
      std::string why = checkedDouble(s, v);
      if (why.empty() && !(v >= 0.0)) why = "must be a finite number >= 0, got " + s;
      return why;
    },
    "NONNEGATIVE");

const CLI::Validator kCount(
    [](std::string& s) -> std::string {
      if (s.empty() || s.size() > 18 || s.find_first_not_of("0123456789") != std::string::npos) {
        return "must be a whole number >= 0, got '" + quoteForMessage(s) + "'";
      }
      return std::string();
    },
    "COUNT");

const CLI::Validator kOutputFile(
    [](std::string& s) -> std::string {
      return s.empty() ? std::string("empty file name: nothing would be written") : std::string();
    },
    "FILE");

void requireDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  namespace fs = std::filesystem;
  std::vector<std::pair<std::string, std::string>> seen;  // canonical path, option
  for (const auto& [option, path] : outputs) {
    if (path.empty()) continue;
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(path, ec);
    const std::string key = ec ? fs::path(path).lexically_normal().string() : canonical.string();
    for (const auto& [other, other_option] : seen) {
      if (other == key) {
        throw UsageError(option + " and " + other_option + " both write '" + quoteForMessage(path) +
                         "'");
      }
    }
    seen.emplace_back(key, option);
  }
}

LoadReport loadWithWarnings(const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud) {
  LoadReport report = loadCloud(path, cloud);
  for (const std::string& w : report.warnings) std::cerr << "warning: " << w << "\n";
  return report;
}

LoadedCloud loadTimed(const std::string& path) {
  const auto t0 = std::chrono::steady_clock::now();
  LoadedCloud loaded;
  loaded.cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  loaded.report = loadWithWarnings(path, *loaded.cloud);
  loaded.seconds = secondsSince(t0);
  return loaded;
}

void addFormatOption(CLI::App& app, std::string& format, const std::vector<std::string>& choices) {
  app.add_option("--format", format, "Output format")
      ->check(CLI::IsMember(choices))
      ->capture_default_str();
}

void emitTable(const Table& table, const std::string& format, const std::string& path) {
  const TableStyle style = format == "csv"        ? TableStyle::Csv
                           : format == "markdown" ? TableStyle::Markdown
                                                  : TableStyle::Aligned;
  emit(table.render(style), path);
}

void emit(const std::string& text, const std::string& path) {
  if (path.empty()) {
    std::cout << text << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write to standard output");
  } else {
    writeTextAtomic(path, text);
  }
}

void addPcdFormatOption(CLI::App& app, std::string& format) {
  app.add_option("--pcd-format", format, "Encoding of PCD files written")
      ->check(CLI::IsMember({"ascii", "binary", "binary_compressed"}))
      ->capture_default_str();
}

}  // namespace metricmap::cli
