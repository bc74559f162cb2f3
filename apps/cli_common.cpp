#include "cli_common.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <optional>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/file_identity.h"
#include "metricmap/mapping/occupancy_map_2d.h"
#include "metricmap/occupancy/octomap_file_check.h"
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

const CLI::Validator kCellEdge(
    [](std::string& s) -> std::string {
      double v = 0.0;
      std::string why = checkedDouble(s, v);
      if (why.empty() && !(v >= kOctomapMinResolution && v <= kOctomapMaxResolution)) {
        why = "'" + quoteForMessage(s) +
              "' is outside the cell edges a map file can hold (0.0001 to 1000 m)";
      }
      return why;
    },
    "EDGE");

namespace {

/// CLI11 converts integers with strtoll's base 0: `010` would be octal 8, `09` refused as
/// unconvertible. Decimal text has no leading zero.
std::string leadingZero(const std::string& s) {
  if (s.size() > 1 && s[0] == '0') {
    return "'" + quoteForMessage(s) +
           "' has a leading zero: write the whole number in decimal without it";
  }
  return std::string();
}

}  // namespace

const CLI::Validator kCount(
    [](std::string& s) -> std::string {
      if (s.empty() || s.size() > 18 || s.find_first_not_of("0123456789") != std::string::npos) {
        return "must be a whole number >= 0, got '" + quoteForMessage(s) + "'";
      }
      return leadingZero(s);
    },
    "COUNT");

CLI::Validator countIn(unsigned long long min, unsigned long long max) {
  return CLI::Validator(
      [min, max](std::string& s) -> std::string {
        const std::string range = std::to_string(min) + " to " + std::to_string(max);
        if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
          return "must be a whole number from " + range + ", got '" + quoteForMessage(s) + "'";
        if (std::string why = leadingZero(s); !why.empty()) return why;
        const std::string top = std::to_string(max);
        const bool above = s.size() > top.size() || (s.size() == top.size() && s > top);
        if (above || std::stoull(s) < min)
          return "'" + quoteForMessage(s) + "' is out of range: " + range;
        return std::string();
      },
      "COUNT");
}

std::string plainNumber(double value) {
  const double a = std::fabs(value);
  const bool plain = a == 0.0 || (a >= 1e-4 && a < 1e15);
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    const bool exponent = std::strchr(buf, 'e') != nullptr;
    if (std::strtod(buf, nullptr) == value && (!plain || !exponent)) return buf;
  }
  return formatNumber(value);  // nan, inf
}

CLI::Validator finiteIn(double min, double max) {
  return CLI::Validator(
      [min, max](std::string& s) -> std::string {
        double v = 0.0;
        std::string why = checkedDouble(s, v);
        if (why.empty() && !(v >= min && v <= max)) {
          why = "'" + quoteForMessage(s) + "' is out of range: " + plainNumber(min) + " to " +
                plainNumber(max);
        }
        return why;
      },
      "NUMBER");
}

CLI::Validator declaredRange(const ParameterSpec& spec) {
  return CLI::Validator(
      [spec](std::string& s) -> std::string {
        double v = 0.0;
        std::string why = checkedDouble(s, v);
        if (why.empty() && !parameterAccepts(spec, v))
          why = "'" + quoteForMessage(s) + "' is out of range: " + spec.name + " must be " +
                parameterRule(spec);
        return why;
      },
      spec.kind == ParameterKind::Real ? "NUMBER" : "INT");
}

CLI::Validator declaredRange(const std::vector<ParameterSpec>& schema, const std::string& name) {
  for (const ParameterSpec& p : schema)
    if (p.name == name) return declaredRange(p);
  throw std::logic_error("no declared parameter " + name);
}

void refuseIgnored(const CLI::App& app, const std::string& option, bool applies,
                   const std::string& why) {
  if (!applies && app.count(option) > 0) throw UsageError(option + " has no effect " + why);
}

std::string givenText(const CLI::App& app, const std::string& option) {
  const CLI::Option* opt = app.get_option_no_throw(option);
  if (opt == nullptr || opt->count() == 0 || opt->results().empty()) return std::string();
  return opt->results().back();
}

const CLI::Validator kOutputFile(
    [](std::string& s) -> std::string {
      return s.empty() ? std::string("empty file name: nothing would be written") : std::string();
    },
    "FILE");

namespace {

/// A path as it may appear in a one-line message: control bytes as \xHH, and when it is very
/// long its end (the file name) kept.
std::string quotePath(const std::string& path) {
  std::string out;
  for (const char ch : path) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    } else {
      out += ch;
    }
  }
  constexpr std::size_t kMax = 240;
  return out.size() <= kMax ? out : "..." + out.substr(out.size() - (kMax - 3));
}

}  // namespace

void requireExtension(const std::string& option, const std::string& path,
                      const std::vector<std::string>& extensions, const std::string& format) {
  if (path.empty()) return;
  for (const std::string& ext : extensions) {
    if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0 &&
        path[path.size() - ext.size() - 1] != '/')
      return;
  }
  std::string list;
  for (std::size_t i = 0; i < extensions.size(); ++i)
    list += (i == 0 ? "" : i + 1 == extensions.size() ? " or " : ", ") + extensions[i];
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
  throw UsageError(option + " '" + quotePath(path) + "': " +
                   (has_ext ? "the extension '" + quoteForMessage(path.substr(dot)) + "'"
                            : std::string("a name without extension")) +
                   " does not name what this option writes (" + format + "): use " + list);
}

std::vector<std::size_t> parseFramesOption(const std::string& text) {
  std::vector<std::size_t> f;
  try {
    f = parseFrameList(text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--frames: ") + e.what());
  }
  for (std::size_t k = 1; k < f.size(); ++k) {
    if (f[k] <= f[k - 1]) {
      throw UsageError("--frames: frames must be in acquisition order without repeats: " +
                       std::to_string(f[k]) + " follows " + std::to_string(f[k - 1]));
    }
  }
  return f;
}

void requireDistinctFiles(const RolePaths& inputs, const RolePaths& outputs) {
  const std::optional<FileClash> clash = findFileClash(inputs, outputs);
  if (!clash) return;
  const auto& [first_role, first_path] = clash->first;
  const auto& [second_role, second_path] = clash->second;
  if (clash->output_is_input) {
    throw UsageError(second_role + " '" + quotePath(second_path) + "' and the " + first_role +
                     " '" + quotePath(first_path) +
                     "' are the same file: an output never replaces an input");
  }
  std::string message =
      second_role + " and " + first_role + " both write '" + quotePath(second_path) + "'";
  if (first_path != second_path) message += " (also named '" + quotePath(first_path) + "')";
  throw UsageError(message);
}

void requireDistinctInputs(const RolePaths& inputs) {
  const auto repeated = findRepeatedInput(inputs);
  if (!repeated) return;
  const auto& [first, second] = *repeated;
  std::string message = second.first + " '" + quotePath(second.second) + "' ";
  message += first.second == second.second ? std::string("is given twice")
                                           : "and the " + first.first + " '" +
                                                 quotePath(first.second) + "' are the same file";
  throw UsageError(message + ": it would be read and counted twice");
}

void requireOccupiedCells(const MapImage& image, std::uint32_t min_hits,
                          const std::string& out_map) {
  if (out_map.empty() || image.width == 0) return;  // an empty band is reported by the caller
  std::uint32_t most = 0;
  for (const std::uint32_t h : image.hits) most = std::max(most, h);
  if (most >= min_hits) return;
  throw InputError("--out-map '" + quotePath(out_map) + "': no cell has --min-hits " +
                   std::to_string(min_hits) + " points (the fullest has " + std::to_string(most) +
                   "): the map would be empty");
}

void requireDistinctOutputs(const RolePaths& outputs) { requireDistinctFiles({}, outputs); }

RolePaths withRole(const std::string& role, const std::vector<std::string>& paths) {
  RolePaths out;
  out.reserve(paths.size());
  for (const std::string& p : paths) out.emplace_back(role, p);
  return out;
}

RolePaths kittiInputs(const std::string& root, const std::string& sequence,
                      const std::vector<std::size_t>& frames, bool with_poses) {
  const KittiSequence seq{root, sequence};
  RolePaths in;
  in.reserve(frames.size() + 2);
  for (const std::size_t f : frames) in.emplace_back("scan", seq.scan(f));
  in.emplace_back("calib file", seq.calib());
  if (with_poses) in.emplace_back("poses file", seq.poses());
  return in;
}

void guardStandardStreams() {
  for (const int fd : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO}) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    // read-only: writes to a closed stdout still fail (EBADF), as the user meant them to
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0 && null != fd) {
      ::dup2(null, fd);
      ::close(null);
    }
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

std::string renderTable(const Table& table, const std::string& format) {
  const TableStyle style = format == "csv"        ? TableStyle::Csv
                           : format == "markdown" ? TableStyle::Markdown
                                                  : TableStyle::Aligned;
  return table.render(style);
}

void emitTable(const Table& table, const std::string& format, const std::string& path) {
  emit(renderTable(table, format), path);
}

void emitTable(const Table& table, const std::string& format, OutputSet& outputs) {
  emit(renderTable(table, format), outputs);
}

namespace {

/// Under an MPI launcher the process's standard output is a pipe or terminal to the launcher,
/// which forwards what it reads and ignores its own write errors: a report written there always
/// "succeeds", even when the launcher's standard output is /dev/full or closed. When the launcher
/// (mpirun, mpiexec, orterun, prterun) is the parent on this host, as Open MPI starts local ranks,
/// the report goes to the launcher's own standard output instead (/proc/PPID/fd/1, appended), so
/// that the one rule holds: the report is printed and checked before outputs are committed.
/// -1: not under a launcher we can reach (print as usual); -2: the launcher's stdout is closed.
int launcherStdout() {
  if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr && std::getenv("PMI_SIZE") == nullptr &&
      std::getenv("PMIX_RANK") == nullptr)
    return -1;
  const pid_t parent = ::getppid();
  char path[64];
  std::snprintf(path, sizeof path, "/proc/%d/comm", static_cast<int>(parent));
  std::FILE* comm = std::fopen(path, "re");
  if (comm == nullptr) return -1;
  char name[32] = {};
  const bool read = std::fgets(name, sizeof name, comm) != nullptr;
  std::fclose(comm);
  if (!read) return -1;
  name[std::strcspn(name, "\n")] = '\0';
  const std::string launcher = name;
  if (launcher != "mpirun" && launcher != "mpiexec" && launcher != "orterun" &&
      launcher != "prterun")
    return -1;
  // The launcher's descriptor 1 must be the standard output it inherited: open for writing and
  // not close-on-exec. When the user closed it (`>&-`), the launcher reuses descriptor 1 for one
  // of its own pipes (read-only, close-on-exec): never write there, that stdout is closed.
  std::snprintf(path, sizeof path, "/proc/%d/fdinfo/1", static_cast<int>(parent));
  std::FILE* info = std::fopen(path, "re");
  if (info == nullptr) return errno == ENOENT ? -2 : -1;
  long flags = -1;
  for (char row[128]; std::fgets(row, sizeof row, info) != nullptr;) {
    if (std::strncmp(row, "flags:", 6) == 0) flags = std::strtol(row + 6, nullptr, 8);
  }
  std::fclose(info);
  if (flags < 0) return -1;
  if ((flags & O_ACCMODE) == O_RDONLY || (flags & O_CLOEXEC) != 0) return -2;
  std::snprintf(path, sizeof path, "/proc/%d/fd/1", static_cast<int>(parent));
  struct stat st {};
  if (::lstat(path, &st) != 0) return errno == ENOENT ? -2 : -1;
  const int fd = ::open(path, O_WRONLY | O_APPEND | O_CLOEXEC | O_NOCTTY);
  return fd >= 0 ? fd : -1;
}

void printChecked(const std::string& text) {
  if (text.empty()) return;
  const int launcher = launcherStdout();
  if (launcher == -2) throw std::runtime_error("cannot write to standard output");
  if (launcher >= 0) {
    std::size_t done = 0;
    bool ok = true;
    while (ok && done < text.size()) {
      const ssize_t n = ::write(launcher, text.data() + done, text.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
      } else if (n < 0 && errno == EINTR) {
        continue;
      } else {
        ok = false;
      }
    }
    ok = ::close(launcher) == 0 && ok;
    if (!ok) throw std::runtime_error("cannot write to standard output");
    return;
  }
  std::cout << text << std::flush;
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0)
    throw std::runtime_error("cannot write to standard output");
}

}  // namespace

void emit(const std::string& text, const std::string& path) {
  if (path.empty()) {
    printChecked(text);
  } else {
    writeTextAtomic(path, text);
  }
}

void emit(const std::string& text, OutputSet& outputs) {
  printChecked(text);  // throws before anything is committed
  outputs.commit();
}

void addPcdFormatOption(CLI::App& app, std::string& format) {
  app.add_option("--pcd-format", format, "Encoding of PCD files written")
      ->check(CLI::IsMember({"ascii", "binary", "binary_compressed"}))
      ->capture_default_str();
}

}  // namespace metricmap::cli
