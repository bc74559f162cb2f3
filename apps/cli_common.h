#pragma once
/// \file cli_common.h
/// \brief Shared pieces of the `metricmap` subcommands: validators, loading, output formats.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <CLI/CLI.hpp>

#include "metricmap/common/parameter_schema.h"

#include "metricmap/io/load_report.h"
#include "metricmap/io/output_set.h"

namespace metricmap {
struct MapImage;
}

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

/// \brief A voxel or map cell edge (m) that a file written with it can be read back with:
/// finite, within OctoMap's accepted `res` range (0.0001 to 1000 m, kOctomapMinResolution..);
/// the map_server YAML and its origin get the same range.
extern const CLI::Validator kCellEdge;

/// \brief A whole number >= 0 written in decimal digits, without leading zeros (CLI11 would read
/// `010` as octal 8 and refuse `09`).
extern const CLI::Validator kCount;

/// \brief A whole number in [min, max] written in decimal digits without leading zeros: checked
/// against the range of the type it is stored in before it is narrowed.
CLI::Validator countIn(unsigned long long min, unsigned long long max);

/// \brief A number as a message shows a value the program chose (a bound, a default): the
/// shortest text that reads back as the same value, in plain decimals between 1e-4 and 1e15
/// (`90`, `179.999`, `0.0001`: never `9e+01` or `90.000000`), with an exponent beyond (`1e-05`,
/// `1e+308`).
std::string plainNumber(double value);

/// \brief A finite decimal number in [min, max]; the message quotes the text given and the
/// bounds as plainNumber (`'1e3' is out of range: -90 to 90`, never `90.000000`).
CLI::Validator finiteIn(double min, double max);

/// \brief A number the library's declaration of a parameter accepts (its range and kind:
/// common/parameter_schema.h), so that an option and `--set` accept the same values.
CLI::Validator declaredRange(const ParameterSpec& spec);

/// \brief declaredRange of the parameter `name` of `schema` (a configuration's declaration).
CLI::Validator declaredRange(const std::vector<ParameterSpec>& schema, const std::string& name);

/// \brief Usage error (exit 2) when `option` was given on `app`'s command line although it has no
/// effect in this run (`applies` false): "OPTION has no effect WHY" (an option
/// is honoured or refused, never dropped silently).
void refuseIgnored(const CLI::App& app, const std::string& option, bool applies,
                   const std::string& why);

/// \brief The text `option` was given as on `app`'s command line (its last occurrence), for
/// messages that quote a value as the user wrote it (`1e5`, not `100000`); "" when not given.
std::string givenText(const CLI::App& app, const std::string& option);

/// \brief An output file name: not empty (`--out ''` would write nothing and succeed).
extern const CLI::Validator kOutputFile;

/// \brief (role, path) pairs: the role is an option ("--out") or what the file is ("input",
/// "poses file"); messages name both.
using RolePaths = std::vector<std::pair<std::string, std::string>>;

/// \brief Usage error (exit 2) when two outputs name one file, or an output names an input.
///
/// Files are compared by identity (metricmap::findFileClash, io/file_identity.h): device and
/// inode of an existing file, the normalised absolute path (symlinked directories resolved) of
/// a new one; so `x`, `./x`, `$PWD/x`, `sub/../x`, a symbolic link and a hard link to `x` are
/// one file. Empty paths are skipped. Call it after parsing, before any input is read or any
/// output staged: the message names both roles and both paths.
void requireDistinctFiles(const RolePaths& inputs, const RolePaths& outputs);

/// \brief Usage error (exit 2) unless `path` ends in one of `extensions` (with the dot, lowercase):
/// an output gets the format its option writes, and its name must say so.
/// `format` names that format in the message. An empty path passes.
void requireExtension(const std::string& option, const std::string& path,
                      const std::vector<std::string>& extensions, const std::string& format);

/// \brief Two inputs naming one file however spelled (`a.pcd ./a.pcd`, a link) would be read
/// and counted twice: a usage error naming both spellings (exit 2).
void requireDistinctInputs(const RolePaths& inputs);

/// \brief A map_server map (--out-map) with no occupied cell would be written as a blank picture:
/// an InputError (exit 1) naming the option, --min-hits and the most hits a cell got.
void requireOccupiedCells(const MapImage& image, std::uint32_t min_hits,
                          const std::string& out_map);

/// \brief requireDistinctFiles with no inputs (two outputs naming one file).
void requireDistinctOutputs(const RolePaths& outputs);

/// \brief Every path of `paths` with the role `role`.
RolePaths withRole(const std::string& role, const std::vector<std::string>& paths);

/// \brief What a KITTI run reads: each frame's scan ("scan"), the calibration ("calib file") and,
/// when `with_poses`, the pose file ("poses file") of `sequence` under `root`.
RolePaths kittiInputs(const std::string& root, const std::string& sequence,
                      const std::vector<std::size_t>& frames, bool with_poses);

/// \brief The frames of a `--frames` list (parseFrameList), which must be in acquisition order
/// without repeats as for `odometry`: a repeated frame would count one scan twice.
/// \throws UsageError "--frames: ..." (exit 2)
std::vector<std::size_t> parseFramesOption(const std::string& text);

/// \brief Keep standard input, output and error open: a closed one is reopened on /dev/null
/// (stdout and stderr read-only, so that writing the report fails) so that no output file is
/// opened as descriptor 0, 1 or 2. Called first in main.
void guardStandardStreams();

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

/// \brief The rule for a command's report and its output files (docs/RELIABILITY.md): print the
/// report to stdout, flush and check it, and only then commit `outputs`. When the report
/// cannot be printed (stdout is a full disk, a closed pipe or closed), std::runtime_error
/// "cannot write to standard output" is thrown and nothing is committed (the OutputSet's
/// destructor removes the temporaries): exit 1, no output. `text` may be empty (the report went
/// to a file of `outputs`).
void emit(const std::string& text, OutputSet& outputs);

/// \brief emitTable's text, then `outputs` committed, as emit(text, outputs).
void emitTable(const class Table& table, const std::string& format, OutputSet& outputs);

/// \brief The text emitTable prints.
std::string renderTable(const class Table& table, const std::string& format);

/// \brief Adds --pcd-format with its check; the value lands in `format`.
void addPcdFormatOption(CLI::App& app, std::string& format);

}  // namespace metricmap::cli
