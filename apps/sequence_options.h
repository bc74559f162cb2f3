#pragma once
/// \file sequence_options.h
/// \brief Options every command that reads a scan source shares: the source, its frames and
/// reference, and the odometry's range window and voxel (given, or from the first scan).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_common.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/registration/lidar_odometry_config.h"
#include "metricmap/sequence/odometry_run.h"
#include "metricmap/sequence/sensor_profile.h"

namespace metricmap::cli {

struct SourceOptions {
  std::string path, format = "auto", sequence = "00", frames, reference, times, topic;
  /// \brief Bag topics a command takes without --topic (ScanSourceOptions::bag_scans): set by
  /// addSourceOptions from the command's name: "laser" for slam2d, "cloud" for odometry, else
  /// "any".
  std::string bag_scans = "any";
};

/// \brief SOURCE (positional), --source-format, --sequence, --frames, --reference, --times,
/// --topic.
void addSourceOptions(CLI::App& app, SourceOptions& o);
/// \brief Usage checks (exit 2): the frame list, and the options the source given would ignore
/// (--sequence on a source other than a KITTI root, --times and --reference on a CARMEN log,
/// which carries its stamps and poses on its lines). \throws CLI::ValidationError, UsageError
void checkSourceOptions(const CLI::App& app, const SourceOptions& o);
/// \brief The files the source reads that an output must not replace (the source path itself,
/// the reference and times files).
RolePaths sourceInputs(const SourceOptions& o);
/// \brief openScanSource with the options; a bag topic that cannot be chosen (none, several,
/// another type: TopicSelectionError) is a usage error (exit 2). \throws UsageError
std::unique_ptr<ScanSource> openSource(const SourceOptions& o);
/// \brief The frames --frames names, or every frame of the source.
/// \throws InputError naming the option and the source for a frame beyond its scans
std::vector<std::size_t> selectedFrames(const SourceOptions& o, const ScanSource& source);

/// \brief runOdometry, its errors naming a file: the range window chosen from the first scan
/// (profileScan) reports a scan with too few points without naming it; here that message is
/// prefixed with the first frame's scan (read again on this error path only).
/// \throws InputError naming the scan, and whatever runOdometry throws
OdometryRun runOdometryNamed(ScanSource& source, const OdometryRunOptions& options,
                             const OdometryObserver& observer = {});

struct RangeOptions {
  std::optional<double> max_range, min_range, voxel_size;
};

/// \brief --max-range, --min-range, --voxel-size and --profile auto|kitti.
void addRangeOptions(CLI::App& app, RangeOptions& o, std::string& profile);
/// \brief --min-range below --max-range when both are given; --profile refused when
/// --max-range, --min-range and --voxel-size are all given (it would set nothing).
/// \throws CLI::ValidationError, UsageError
void checkRangeOptions(const CLI::App& app, const RangeOptions& o);
/// \brief The KITTI preset (`profile` "kitti", the default for a KITTI source: the
/// LidarOdometryConfig defaults) or values from the first scan ("auto", the default for other
/// sources); the values given on the command line replace either.
void applyRangeOptions(const RangeOptions& o, const std::string& profile, const SourceInfo& info,
                       LidarOdometryConfig& config, SensorProfileRequest& request);

}  // namespace metricmap::cli
