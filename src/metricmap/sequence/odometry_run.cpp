#include "metricmap/sequence/odometry_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "metricmap/exceptions.h"
#include "metricmap/registration/deskew.h"
#include "metricmap/registration/scan_registration.h"

namespace metricmap {
namespace {

double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

Eigen::Isometry3d inverseOf(const Eigen::Isometry3d& t) {
  Eigen::Isometry3d i;
  i.matrix() = t.matrix().inverse();  // KITTI's Tr is orthonormal only to ~1e-7
  return i;
}

std::vector<std::size_t> selectFrames(const std::vector<std::size_t>& frames, ScanSource& source) {
  const std::size_t n = source.size();
  if (frames.empty()) {
    std::vector<std::size_t> all(n);
    for (std::size_t i = 0; i < n; ++i) all[i] = i;
    return all;
  }
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (frames[k] >= n) source.scan(frames[k]);  // throws InputError naming the source
    if (k > 0 && frames[k] <= frames[k - 1]) {
      throw std::invalid_argument(
          "frames must be in acquisition order without repeats: " + std::to_string(frames[k]) +
          " follows " + std::to_string(frames[k - 1]));
    }
  }
  return frames;
}

// Per-point times as fractions of the sweep, for deskew.
std::vector<double> sweepFractions(const Scan& scan, DeskewMode mode, bool& used) {
  used = false;
  if (mode == DeskewMode::Off) return {};
  if (mode == DeskewMode::Azimuth) {
    used = true;
    return azimuthTimes(toPoints3d(scan.points));
  }
  if (scan.point_times.empty()) return {};
  const double span = *std::max_element(scan.point_times.begin(), scan.point_times.end());
  if (!(span > 0.0)) return {};
  std::vector<double> t(scan.point_times.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = scan.point_times[i] / span;
  used = true;
  return t;
}

}  // namespace

const char* worldFrameName(WorldFrame w) { return w == WorldFrame::Level ? "level" : "first-scan"; }

WorldFrame parseWorldFrame(const std::string& name) {
  if (name == "level") return WorldFrame::Level;
  if (name == "first-scan") return WorldFrame::FirstScan;
  throw std::invalid_argument("world frame must be level or first-scan, got '" + name + "'");
}

OdometryRun runOdometry(ScanSource& source, const OdometryRunOptions& options,
                        const OdometryObserver& observer) {
  const std::vector<std::size_t> frames = selectFrames(options.frames, source);
  const SourceInfo& info = source.info();
  OdometryRun run;
  run.convention = info.conventions.pose_frame;
  // Output convention: A P A^-1 (A = sensor -> base where the source's poses are the base's,
  // as KITTI's camera 0 poses).
  const Eigen::Isometry3d a =
      info.conventions.poses_of_base ? info.sensor_to_base : Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d a_inv = inverseOf(a);
  const bool has_ref = info.reference.size() >= source.size();

  std::optional<LidarOdometry> odometry;
  std::vector<Eigen::Isometry3d> ref_out;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    auto t = std::chrono::steady_clock::now();
    Scan scan = source.scan(frames[k]);
    run.read_seconds += msSince(t) * 1e-3;
    if (!odometry) {
      LidarOdometryConfig config = options.config;
      const SensorProfileRequest& req = options.profile;
      if (req.max_range || req.min_range || req.voxel_size) {
        run.profile = profileScan(toPoints3d(scan.points));
      }
      if (req.motion && info.stamps.size() == source.size()) {
        std::vector<double> stamps;
        for (std::size_t f : frames) stamps.push_back(info.stamps[f]);
        profileStamps(run.profile, stamps);
      }
      config = applyProfile(config, run.profile, req);
      bool deskew = false;
      sweepFractions(scan, options.deskew, deskew);
      config.deskew = deskew;
      run.deskewed = deskew;
      run.config = config;
      odometry.emplace(config);
      if (options.world == WorldFrame::Level && !info.conventions.poses_of_base) {
        try {
          run.up = estimateUp(toPoints3d(scan.points));
        } catch (const InputError& e) {
          throw InputError(scan.name + ": " + e.what() + " (--world-frame first-scan keeps the " +
                           "first scan's frame)");
        }
        run.level = levelRotation(run.up->up);
        run.world = WorldFrame::Level;
      }
    }
    bool used = false;
    const std::vector<double> times = sweepFractions(scan, options.deskew, used);
    if (used != run.deskewed) {
      throw InputError(scan.name + (used
                                        ? ": per-point times present, where the first scan had none"
                                        : ": per-point times missing, unlike the first scan's"));
    }
    t = std::chrono::steady_clock::now();
    OdometryFrame f;
    f.result = odometry->registerFrame(scan.points, times, scan.name);
    f.ms = msSince(t);
    f.index = frames[k];
    f.name = scan.name;
    f.stamp = scan.stamp;
    const Eigen::Isometry3d pose = run.level * a * f.result.pose * a_inv;
    run.trajectory.poses.push_back(pose);
    if (std::isfinite(scan.stamp)) run.trajectory.stamps.push_back(scan.stamp);
    if (has_ref) ref_out.push_back(a * info.reference.poses[frames[k]] * a_inv);  // own world
    if (k > 0) {
      const Eigen::Isometry3d motion = inverseOf(run.trajectory.poses[k - 1]) * pose;
      f.step_m = motion.translation().norm();
      if (has_ref) {
        const PoseError e = poseError(inverseOf(ref_out[k - 1]) * ref_out[k], motion);
        f.diff_m = e.translation;
        f.diff_deg = e.rotation_deg;
      }
    }
    run.frames.push_back(std::move(f));
    if (observer) observer(run.frames.back(), k + 1, frames.size());
  }
  if (run.trajectory.stamps.size() != run.trajectory.poses.size()) run.trajectory.stamps.clear();
  if (has_ref) {
    run.reference.poses = std::move(ref_out);
    run.reference.stamps = run.trajectory.stamps;
    run.rpe = relativeError(run.trajectory.poses, run.reference.poses);
    run.failed_steps = findStepFailures(*run.rpe);
  }
  return run;
}

}  // namespace metricmap
