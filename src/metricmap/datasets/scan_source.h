#pragma once
/// \file scan_source.h
/// \brief Scan sources: one interface over every place scans come from (the KITTI odometry
/// layout, a folder or list of cloud files, CARMEN laser logs). A source yields scans in
/// acquisition order, each in its sensor frame, and says what else it knows (extrinsic,
/// reference poses, stamps). Sources read lazily: one scan in memory at a time.

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include "metricmap/common/trajectory.h"
#include "metricmap/io/laser_scan.h"

namespace metricmap {

/// \brief One scan as a source yields it.
struct Scan {
  /// \brief Points in the sensor frame (NaN where a beam gave no return).
  pcl::PointCloud<pcl::PointXYZ> points;
  /// \brief Per-point intensity, empty when the data has none.
  std::vector<float> intensity;
  /// \brief Per-point time in seconds relative to `stamp` (may be negative), empty when the data
  /// has none.
  std::vector<double> point_times;
  /// \brief Time stamp (seconds), NaN when unknown.
  double stamp = std::numeric_limits<double>::quiet_NaN();
  /// \brief Position in the source (0-based).
  std::size_t index = 0;
  /// \brief How messages name this scan: the file path, or "LOG: line N".
  std::string name;
  /// \brief The 2D scan as beams, for planar laser sources (CARMEN logs); points hold the same
  /// beams at z = 0.
  std::optional<LaserScan> laser;
  /// \brief The raw odometry pose (base -> odometry world) the log gives with this scan.
  std::optional<Eigen::Isometry3d> odometry;
};

/// \brief What a source knows beyond its scans.
/// \brief How a source's poses and maps are expressed: what the code outside the sources needs
/// to know of a source, so that nothing asks a source its name.
struct SourceConventions {
  /// \brief The world's up axis in the pose frame (KITTI's camera 0: -y).
  Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  /// \brief True when poses are given and written as poses of the base frame (A P A^-1 with
  /// A = sensor_to_base: KITTI's camera 0 poses), false when they are sensor poses.
  bool poses_of_base = false;
  /// \brief The name of the frame poses are written in ("sensor", "kitti camera 0").
  std::string pose_frame = "sensor";
  /// \brief The sensor profile used when none is given: "auto" (chosen from the first scan) or
  /// a named preset ("kitti").
  std::string default_profile = "auto";
};

struct SourceInfo {
  /// \brief "kitti", "folder", "carmen" or "bag".
  std::string kind;
  /// \brief The path the source was opened from.
  std::string path;
  /// \brief Sensor -> base (vehicle / robot) frame. KITTI: Tr (velodyne -> camera 0).
  Eigen::Isometry3d sensor_to_base = Eigen::Isometry3d::Identity();
  /// \brief Reference poses of the sensor (sensor -> reference world), one per scan, when the
  /// source has them (KITTI poses/NN.txt, a folder's poses.txt); empty otherwise.
  Trajectory reference;
  /// \brief Where the reference came from (empty: none).
  std::string reference_path;
  /// \brief One stamp per scan when known (times.txt, the log), else empty.
  std::vector<double> stamps;
  /// \brief True when the scans carry per-point times.
  bool point_times = false;
  /// \brief True when the scans are planar (2D laser).
  bool planar = false;
  /// \brief Up axis, pose frame and default sensor profile of this source.
  SourceConventions conventions;
};

/// \brief Scans from one place, in acquisition order. Not thread-safe.
class ScanSource {
 public:
  virtual ~ScanSource() = default;
  /// \brief Number of scans.
  virtual std::size_t size() const = 0;
  /// \brief Scan i (0-based). Cheapest in increasing order; a sequential source (a compressed
  /// log) reads again from its start to go back.
  /// \throws InputError naming the file when the scan cannot be read, or naming the source
  /// when i >= size()
  virtual Scan scan(std::size_t i) = 0;
  /// \brief What the source knows.
  virtual const SourceInfo& info() const = 0;
};

/// \brief How to open a source.
struct ScanSourceOptions {
  /// \brief "auto" (from the path), "kitti", "folder", "carmen" or "bag".
  std::string format = "auto";
  /// \brief KITTI sequence under the root.
  std::string sequence = "00";
  /// \brief Reference pose file (KITTI 12-number or TUM 8-number rows) overriding the one the
  /// source finds; empty: the source's own, if any.
  std::string reference_poses;
  /// \brief Stamps file (one number per line) overriding the one the source finds.
  std::string times;
  /// \brief Bag topic to read (bag_source.h); empty: the bag's only topic of `bag_scans`.
  std::string topic;
  /// \brief Which bag topics are candidates when `topic` is empty: "any" (PointCloud2 and
  /// LaserScan), "cloud" (PointCloud2: 3D odometry) or "laser" (LaserScan: 2D SLAM).
  std::string bag_scans = "any";
};

/// \brief The kind of source openScanSource opens for `path` read as `format` ("auto",
/// "kitti", "folder", "carmen", "bag"): one of those, or "" when it would refuse the
/// path (missing, or none of these). Reads nothing but the file system's entries.
std::string scanSourceKind(const std::string& path, const std::string& format);

/// \brief Why a source of `kind` (scanSourceKind) would ignore the option `option` ("sequence",
/// "times", "reference_poses" or "topic") if it were given, or "" when the option applies (or
/// the kind is unknown: the source itself refuses the path then). Callers refuse a given option
/// the source would ignore, with this reason.
std::string ignoredSourceOption(const std::string& kind, const std::string& option);

/// \brief Open the source at `path`: a KITTI odometry root (has sequences/), a folder of scans
/// (.pcd .ply .bin .npy, one format), a list file (.txt of scan paths) or a CARMEN log
/// (.clf/.log, optionally .gz/.bz2) or a ROS bag (.db3, .mcap, a rosbag2 folder with
/// metadata.yaml: bag_source.h).
/// \throws InputError naming the path when it is none of these or its files are inconsistent
/// \throws std::invalid_argument for a bad option value
std::unique_ptr<ScanSource> openScanSource(const std::string& path,
                                           const ScanSourceOptions& options = {});

}  // namespace metricmap
