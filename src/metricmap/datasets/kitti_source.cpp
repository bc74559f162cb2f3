#include "metricmap/datasets/kitti_source.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/datasets/reference_file.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/scan_file.h"
#include "metricmap/io/trajectory.h"

namespace metricmap {
namespace fs = std::filesystem;

bool looksLikeKittiRoot(const std::string& root) {
  std::error_code ec;
  return fs::is_directory(fs::path(root) / "sequences", ec);
}

namespace {

// The number of a frame file "NNNNNN.bin", or -1.
long frameNumber(const std::string& name) {
  if (name.size() != 10 || name.compare(6, 4, ".bin") != 0) return -1;
  for (int i = 0; i < 6; ++i) {
    if (name[i] < '0' || name[i] > '9') return -1;
  }
  return std::stol(name.substr(0, 6));
}

class KittiSource : public ScanSource {
 public:
  KittiSource(const std::string& root, const ScanSourceOptions& o) : seq_{root, o.sequence} {
    const std::string velodyne = root + "/sequences/" + o.sequence + "/velodyne";
    std::error_code ec;
    if (!fs::is_directory(velodyne, ec)) throw InputError(velodyne + ": no such folder");
    long highest = -1;
    for (fs::directory_iterator it(velodyne, ec), end; !ec && it != end; it.increment(ec)) {
      highest = std::max(highest, frameNumber(it->path().filename().string()));
    }
    if (ec) throw InputError(velodyne + ": cannot list (" + ec.message() + ")");
    if (highest < 0) throw InputError(velodyne + ": no NNNNNN.bin scan");
    size_ = static_cast<std::size_t>(highest) + 1;

    info_.kind = "kitti";
    info_.path = root;
    info_.sensor_to_base = readKittiCalibTr(seq_.calib());
    // Poses in camera 0 of the first frame: y points down, maps lie in its x-z plane.
    info_.conventions.up = Eigen::Vector3f(0, -1, 0);
    info_.conventions.poses_of_base = true;
    info_.conventions.pose_frame = "kitti camera 0";
    info_.conventions.default_profile = "kitti";
    const std::string times =
        !o.times.empty() ? o.times : root + "/sequences/" + o.sequence + "/times.txt";
    if (!o.times.empty() || access(times.c_str(), F_OK) == 0) {
      // KITTI's times.txt covers the whole sequence: read as many stamps as it has.
      info_.stamps = readStampsFile(times, kAnyCount);
      if (info_.stamps.size() < size_) {
        throw InputError(times + ": " + std::to_string(info_.stamps.size()) + " stamp(s) for " +
                         std::to_string(size_) + " scan(s)");
      }
      info_.stamps.resize(size_);
    }
    const std::string poses = !o.reference_poses.empty() ? o.reference_poses : seq_.poses();
    if (!o.reference_poses.empty() || access(poses.c_str(), F_OK) == 0) {
      Trajectory camera = readTrajectoryFile(poses);
      if (camera.size() < size_) {
        throw InputError(poses + ": " + std::to_string(camera.size()) + " pose(s) for " +
                         std::to_string(size_) + " scan(s)");
      }
      info_.reference.poses.reserve(size_);
      for (std::size_t i = 0; i < size_; ++i) {
        info_.reference.poses.push_back(
            kittiScanToWorld(camera.poses[i], info_.sensor_to_base, KittiWorld::Velodyne));
      }
      info_.reference.stamps = info_.stamps;
      info_.reference_path = poses;
    }
  }

  std::size_t size() const override { return size_; }
  const SourceInfo& info() const override { return info_; }

  Scan scan(std::size_t i) override {
    Scan s;
    s.index = i;
    s.name = seq_.scan(i);
    if (i >= size_ || access(s.name.c_str(), F_OK) != 0)
      throw InputError(s.name + ": missing frame");
    ScanFile f = readScanFile(s.name);
    s.points = std::move(f.points);
    s.intensity = std::move(f.intensity);
    if (!info_.stamps.empty()) s.stamp = info_.stamps[i];
    return s;
  }

 private:
  KittiSequence seq_;
  std::size_t size_ = 0;
  SourceInfo info_;
};

}  // namespace

std::unique_ptr<ScanSource> openKittiSource(const std::string& root,
                                            const ScanSourceOptions& options) {
  return std::make_unique<KittiSource>(root, options);
}

}  // namespace metricmap
