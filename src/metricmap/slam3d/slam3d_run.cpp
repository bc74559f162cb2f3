#include "metricmap/slam3d/slam3d_run.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/sequence/sensor_profile.h"

namespace metricmap {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::vector<std::size_t> selectFrames(const std::vector<std::size_t>& frames, ScanSource& source) {
  if (frames.empty()) {
    std::vector<std::size_t> all(source.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    return all;
  }
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (frames[k] >= source.size()) source.scan(frames[k]);  // throws InputError naming it
    if (k > 0 && frames[k] <= frames[k - 1])
      throw std::invalid_argument(
          "frames must be in acquisition order without repeats: " + std::to_string(frames[k]) +
          " follows " + std::to_string(frames[k - 1]));
  }
  return frames;
}

}  // namespace

Slam3DRun runSlam3D(ScanSource& source, const Slam3DRunOptions& options,
                    const Slam3DProgress& progress) {
  Slam3DRun run;
  run.slam = std::make_unique<Slam3D>(options.slam);
  run.frames = selectFrames(options.odometry.frames, source);
  std::unique_ptr<LidarOdometry> odometry;
  bool deskew = false;
  bool stamps = true;
  std::vector<Eigen::Isometry3d> odometry_poses;
  for (std::size_t k = 0; k < run.frames.size(); ++k) {
    auto t = Clock::now();
    Scan scan = source.scan(run.frames[k]);
    run.read_seconds += since(t);
    t = Clock::now();
    if (!odometry) {
      LidarOdometryConfig config = options.odometry.config;
      const SensorProfileRequest& req = options.odometry.profile;
      if (req.max_range || req.min_range || req.voxel_size)
        config = applyProfile(config, profileScan(toPoints3d(scan.points)), req);
      deskew = options.odometry.deskew == DeskewMode::Auto && !scan.point_times.empty();
      if (options.odometry.deskew == DeskewMode::Azimuth)
        throw std::invalid_argument("slam3d: azimuth deskew is not supported, use auto or off");
      config.deskew = deskew;
      run.odometry_config = config;
      odometry = std::make_unique<LidarOdometry>(config);
    }
    std::vector<double> times;
    if (deskew) {
      if (scan.point_times.empty())
        throw InputError(scan.name + ": per-point times missing, unlike the first scan's");
      const double span = *std::max_element(scan.point_times.begin(), scan.point_times.end());
      times.resize(scan.point_times.size());
      for (std::size_t i = 0; i < times.size(); ++i)
        times[i] = span > 0.0 ? scan.point_times[i] / span : 0.0;
    }
    const OdometryResult r = odometry->registerFrame(scan.points, times, scan.name);
    run.odometry_seconds += since(t);
    t = Clock::now();
    run.slam->addScan(scan.points, r.pose);
    run.slam_seconds += since(t);
    odometry_poses.push_back(r.pose);
    if (std::isfinite(scan.stamp))
      run.odometry.stamps.push_back(scan.stamp);
    else
      stamps = false;
    if (progress) progress(k + 1, run.frames.size(), *run.slam);
  }
  const auto t = Clock::now();
  run.slam->finish();
  run.slam_seconds += since(t);
  if (!stamps) run.odometry.stamps.clear();
  run.trajectory.stamps = run.odometry.stamps;
  // Output convention: A P A^-1 with A = sensor -> base where the source's poses are the
  // base's (KITTI's camera 0); map poses A P (the sensor in the frame of the first base).
  const SourceInfo& info = source.info();
  Eigen::Isometry3d a = Eigen::Isometry3d::Identity();
  if (info.conventions.poses_of_base) a = info.sensor_to_base;
  Eigen::Isometry3d a_inv;
  a_inv.matrix() = a.matrix().inverse();
  for (const Eigen::Isometry3d& p : odometry_poses) run.odometry.poses.push_back(a * p * a_inv);
  for (const Eigen::Isometry3d& p : run.slam->poses()) {
    run.trajectory.poses.push_back(a * p * a_inv);
    run.map_poses.push_back(a * p);
  }
  return run;
}

}  // namespace metricmap
