#include "sequence_options.h"

#include <filesystem>
#include <iostream>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/datasets/bag_source.h"
#include "metricmap/datasets/carmen_source.h"
#include "metricmap/datasets/folder_source.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/bag_reader.h"

namespace metricmap::cli {

void addSourceOptions(CLI::App& app, SourceOptions& o) {
  // The bag topic a command takes by default: the one kind of scan it reads.
  o.bag_scans = app.get_name() == "slam2d" || app.get_name() == "localize" ? "laser"
                : app.get_name() == "odometry"                             ? "cloud"
                                                                           : "any";
  app.add_option("source", o.path,
                 "Scans: a KITTI odometry root (sequences/), a folder of .pcd/.ply/.bin/.npy "
                 "scans, a .txt list of scans, a CARMEN log (.clf/.log, .gz/.bz2), or a ROS "
                 "bag (.db3, .mcap, a rosbag2 folder)")
      ->required();
  app.add_option("--source-format", o.format, "How to read SOURCE")
      ->check(CLI::IsMember({"auto", "kitti", "folder", "carmen", "bag"}))
      ->capture_default_str();
  app.add_option("--sequence", o.sequence, "KITTI sequence number")->capture_default_str();
  app.add_option("--frames", o.frames,
                 "Scans in acquisition order, e.g. 0-100,120 (indices from 0; default: all)");
  app.add_option("--reference", o.reference,
                 "Reference poses to compare with (KITTI or TUM rows, one per scan); default: "
                 "poses/NN.txt (KITTI) or poses.txt beside the scans")
      ->check(CLI::ExistingFile);
  app.add_option("--times", o.times, "Scan stamps, one per line; default: times.txt")
      ->check(CLI::ExistingFile);
  app.add_option("--topic", o.topic,
                 "Bag topic (sensor_msgs/msg/PointCloud2 or LaserScan); default: the bag's only "
                 "one");
}

void checkSourceOptions(const CLI::App& app, const SourceOptions& o) {
  // Options the source would ignore: refused, never dropped silently.
  const std::string kind = scanSourceKind(o.path, o.format);
  for (const auto& [field, option] :
       {std::pair{"sequence", "--sequence"}, std::pair{"times", "--times"},
        std::pair{"reference_poses", "--reference"}, std::pair{"topic", "--topic"}}) {
    const std::string why = ignoredSourceOption(kind, field);
    refuseIgnored(app, option, why.empty(), why);
  }
  if (o.frames.empty()) {
    if (app.count("--frames") > 0)
      throw CLI::ValidationError("--frames",
                                 "the frame list is empty (omit --frames for all frames)");
    return;
  }
  std::vector<std::size_t> f;
  try {
    f = parseFrameList(o.frames);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--frames", e.what());
  }
  for (std::size_t k = 1; k < f.size(); ++k) {
    if (f[k] <= f[k - 1]) {
      throw CLI::ValidationError("--frames",
                                 "frames must be in acquisition order without "
                                 "repeats: " +
                                     std::to_string(f[k]) + " follows " + std::to_string(f[k - 1]));
    }
  }
}

RolePaths sourceInputs(const SourceOptions& o) {
  RolePaths in;
  std::error_code ec;
  if (!std::filesystem::is_directory(o.path, ec)) in.push_back({"source", o.path});
  if (!o.reference.empty()) in.push_back({"--reference", o.reference});
  if (!o.times.empty()) in.push_back({"--times", o.times});
  // The scans themselves: a folder's or a list's, or the KITTI sequence's velodyne/ ...
  const std::filesystem::path d(o.path);
  const std::filesystem::path velodyne = d / "sequences" / o.sequence / "velodyne";
  if (std::filesystem::is_directory(d, ec) && looksLikeBag(o.path)) {  // a rosbag2 folder
    for (const auto& e : std::filesystem::directory_iterator(d, ec))
      if (e.is_regular_file(ec)) in.push_back({"bag file", e.path().string()});
    return in;
  }
  if (std::filesystem::is_directory(velodyne, ec)) {
    for (const auto& e : std::filesystem::directory_iterator(velodyne, ec)) {
      if (e.is_regular_file(ec)) in.push_back({"scan", e.path().string()});
    }
  } else if (std::filesystem::is_directory(d, ec) || d.extension() == ".txt") {
    try {
      for (const std::string& p : folderScanPaths(o.path)) in.push_back({"scan", p});
    } catch (const InputError&) {  // an unreadable folder or list is reported when opened
    }
  }
  if (std::filesystem::is_directory(o.path, ec)) {
    // ... and the files the source reads beside them.
    for (const auto& p :
         {d / "poses.txt", d / "times.txt", d / "poses" / (o.sequence + ".txt"),
          d / "sequences" / o.sequence / "times.txt", d / "sequences" / o.sequence / "calib.txt"}) {
      if (std::filesystem::exists(p, ec)) in.push_back({"source file", p.string()});
    }
  }
  return in;
}

std::unique_ptr<ScanSource> openSource(const SourceOptions& o) {
  ScanSourceOptions so;
  so.format = o.format;
  so.sequence = o.sequence;
  so.reference_poses = o.reference;
  so.times = o.times;
  so.topic = o.topic;
  so.bag_scans = o.bag_scans;
  std::unique_ptr<ScanSource> source;
  try {
    source = openScanSource(o.path, so);
  } catch (const TopicSelectionError& e) {
    throw UsageError(e.what());
  }
  // Lines a log source skipped are reported, never dropped silently.
  if (const auto* carmen = dynamic_cast<const CarmenSource*>(source.get()))
    for (const std::string& w : carmen->warnings()) std::cerr << "warning: " << w << "\n";
  return source;
}

std::vector<std::size_t> selectedFrames(const SourceOptions& o, const ScanSource& source) {
  std::vector<std::size_t> frames;
  if (o.frames.empty()) {
    for (std::size_t i = 0; i < source.size(); ++i) frames.push_back(i);
    return frames;
  }
  frames = parseFrameList(o.frames);
  for (std::size_t f : frames) {
    if (f >= source.size()) {
      throw InputError("--frames " + o.frames + ": frame " + std::to_string(f) + " is beyond " +
                       source.info().path + " (" + std::to_string(source.size()) + " scans)");
    }
  }
  return frames;
}

OdometryRun runOdometryNamed(ScanSource& source, const OdometryRunOptions& options,
                             const OdometryObserver& observer) {
  try {
    return runOdometry(source, options, observer);
  } catch (const UsageError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    std::string what = e.what();
    if (what.rfind("the first scan has ", 0) != 0) throw;
    // "finite points": the points at a finite, non-zero range (all-zero points are finite)
    const std::string finite = " finite points;";
    if (const auto at = what.find(finite); at != std::string::npos)
      what.replace(at, finite.size(), " points at a finite, non-zero range;");
    const std::size_t first = options.frames.empty() ? 0 : options.frames.front();
    throw InputError(source.scan(first).name + ": " + what);
  }
}

void addRangeOptions(CLI::App& app, RangeOptions& o, std::string& profile) {
  app.add_option("--profile", profile,
                 "Range window and voxel: kitti (100 m, 3 m, 1 m voxel; the default for a KITTI "
                 "source) or auto (from the first scan's ranges; the default otherwise); "
                 "--max-range, --min-range and --voxel-size given replace the profile's values")
      ->check(CLI::IsMember({"auto", "kitti"}));
  app.add_option("--max-range", o.max_range, "Drop returns farther (m); local map radius")
      ->check(kFinitePositive);
  app.add_option("--min-range", o.min_range, "Drop returns closer (m)")->check(kFiniteNonNegative);
  app.add_option("--voxel-size", o.voxel_size, "Local map voxel (m)")->check(kFinitePositive);
}

void checkRangeOptions(const CLI::App& app, const RangeOptions& o) {
  refuseIgnored(app, "--profile", !(o.max_range && o.min_range && o.voxel_size),
                "with --max-range, --min-range and --voxel-size all given: it sets only the values "
                "not given");
  // A range beyond 10 km or a voxel outside 1 mm .. 100 m is no sensor's: the map's 21-bit cells
  // would overflow or a single cell would hold the whole scan.
  if (o.max_range && *o.max_range > 1e4) {
    throw UsageError("--max-range: '" + quoteForMessage(givenText(app, "--max-range")) +
                     "' is out of range: at most 10000 m");
  }
  if (o.min_range && *o.min_range > 1e4) {
    throw UsageError("--min-range: '" + quoteForMessage(givenText(app, "--min-range")) +
                     "' is out of range: at most 10000 m");
  }
  if (o.voxel_size && !(*o.voxel_size >= 1e-3 && *o.voxel_size <= 100.0)) {
    throw UsageError("--voxel-size: '" + quoteForMessage(givenText(app, "--voxel-size")) +
                     "' is out of range: 0.001 to 100 m");
  }
  if (o.min_range && o.max_range && !(*o.min_range < *o.max_range)) {
    throw UsageError("--min-range '" + quoteForMessage(givenText(app, "--min-range")) +
                     "' must be below --max-range '" +
                     quoteForMessage(givenText(app, "--max-range")) + "'");
  }
}

void applyRangeOptions(const RangeOptions& o, const std::string& profile, const SourceInfo& info,
                       LidarOdometryConfig& config, SensorProfileRequest& request) {
  const bool automatic =
      profile.empty() ? info.conventions.default_profile == "auto" : profile == "auto";
  request.max_range = automatic && !o.max_range;
  request.min_range = automatic && !o.min_range;
  request.voxel_size = automatic && !o.voxel_size;
  if (o.max_range) config.max_range = *o.max_range;
  if (o.min_range) config.min_range = *o.min_range;
  if (o.voxel_size) config.voxel_size = *o.voxel_size;
  if (!(config.min_range < config.max_range) && !request.min_range && !request.max_range) {
    throw UsageError("--min-range " + formatNumber(config.min_range) +
                     " must be below the range window's maximum " + formatNumber(config.max_range) +
                     " m");
  }
}

}  // namespace metricmap::cli
