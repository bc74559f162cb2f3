#include "metricmap/sequence/sensor_profile.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace metricmap {
namespace {

constexpr double kRangeFactor = 1.25;
constexpr double kMaxRange = 100.0, kMinMaxRange = 10.0;
constexpr double kVoxelPerRange = 1.0 / 75.0, kMinVoxel = 0.1, kMaxVoxel = 1.0;
constexpr double kMinRangeCap = 3.0;
constexpr double kCoarseBelow = 0.75, kCoarseFactor = 3.0, kThresholdCap = 2.0;
constexpr double kFineConvergence = 3e-4;
constexpr double kKeyframeInterval = 0.3;
constexpr int kKeyframeHypotheses = 3;

double percentile(std::vector<double>& v, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

SensorProfile profileScan(const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> ranges;
  ranges.reserve(points.size());
  for (const Eigen::Vector3d& p : points) {
    const double r = p.norm();
    if (std::isfinite(r) && r > 0.0) ranges.push_back(r);
  }
  if (ranges.size() < 100) {
    throw std::invalid_argument("the first scan has " + std::to_string(ranges.size()) +
                                " finite points; at least 100 are needed to choose the range "
                                "window and voxel (give --max-range, --min-range, --voxel-size)");
  }
  SensorProfile p;
  p.used = true;
  p.median_range = percentile(ranges, 0.5);
  p.p995_range = percentile(ranges, 0.995);
  const double p005 = percentile(ranges, 0.005);
  p.max_range = std::clamp(kRangeFactor * p.p995_range, kMinMaxRange, kMaxRange);
  p.voxel_size = std::clamp(kVoxelPerRange * p.max_range, kMinVoxel, kMaxVoxel);
  p.min_range = std::min(kMinRangeCap, p005);
  if (p.voxel_size <= kCoarseBelow) {
    p.coarse_voxel_size = kCoarseFactor * p.voxel_size;
    p.max_threshold = kThresholdCap * p.voxel_size;
    p.convergence = kFineConvergence;
  }
  return p;
}

void profileStamps(SensorProfile& profile, const std::vector<double>& stamps) {
  std::vector<double> d;
  for (std::size_t i = 1; i < stamps.size(); ++i) {
    const double dt = stamps[i] - stamps[i - 1];
    if (std::isfinite(dt) && dt > 0.0) d.push_back(dt);
  }
  profile.scan_interval = d.empty() ? 0.0 : percentile(d, 0.5);
  profile.keyframes = profile.scan_interval >= kKeyframeInterval;
}

LidarOdometryConfig applyProfile(LidarOdometryConfig config, const SensorProfile& profile,
                                 const SensorProfileRequest& request) {
  if (request.motion && profile.keyframes) {
    config.prediction_rotation = 0.0;
    config.min_support = 1.0;
    config.hypothesis_count = kKeyframeHypotheses;
  }
  if (!profile.used) return config;
  if (request.max_range) config.max_range = profile.max_range;
  if (request.min_range) config.min_range = profile.min_range;
  if (request.voxel_size) {
    config.voxel_size = profile.voxel_size;
    config.coarse_voxel_size = profile.coarse_voxel_size;
    config.max_threshold = profile.max_threshold;
    if (profile.convergence > 0.0) config.convergence = profile.convergence;
  }
  if (!(config.min_range < config.max_range)) {
    // Only a chosen minimum yields to the window's maximum; a given one is never replaced.
    if (!request.min_range) {
      std::ostringstream msg;
      msg << "min_range " << config.min_range << " m (given) is not below the max_range "
          << config.max_range << " m "
          << (request.max_range ? "chosen from the first scan's ranges" : "given")
          << ": give a max_range above it";
      throw std::invalid_argument(msg.str());
    }
    config.min_range = 0.0;
  }
  return config;
}

const std::vector<std::string>& sensorProfileNames() {
  static const std::vector<std::string> names = {"auto", "kitti"};
  return names;
}

}  // namespace metricmap
