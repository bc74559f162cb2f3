#include "metricmap/registration/lidar_odometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "metricmap/common/format_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/registration/deskew.h"
#include "metricmap/registration/motion_hypotheses.h"
#include "metricmap/registration/point_to_point_icp.h"
#include "metricmap/registration/voxel_downsample.h"

namespace metricmap {
namespace {

const LidarOdometryConfig& validated(const LidarOdometryConfig& c) {
  auto positive = [](double v, const char* name) {
    if (!(std::isfinite(v) && v > 0.0)) {
      throw std::invalid_argument(std::string(name) + " must be a finite number > 0, got " +
                                  formatNumber(v));
    }
  };
  positive(c.max_range, "max_range");
  positive(c.voxel_size, "voxel_size");
  positive(c.initial_threshold, "initial_threshold");
  positive(c.convergence, "convergence");
  if (!(std::isfinite(c.min_range) && c.min_range >= 0.0 && c.min_range < c.max_range)) {
    throw std::invalid_argument("min_range must be >= 0 and below max_range, got " +
                                formatNumber(c.min_range));
  }
  for (auto [v, name] :
       {std::pair{c.min_threshold, "min_threshold"}, std::pair{c.min_deviation, "min_deviation"},
        std::pair{c.degeneracy_ratio, "degeneracy_ratio"},
        std::pair{c.min_inlier_fraction, "min_inlier_fraction"},
        std::pair{c.max_threshold, "max_threshold"},
        std::pair{c.coarse_voxel_size, "coarse_voxel_size"},
        std::pair{c.support_distance, "support_distance"}}) {
    if (!(std::isfinite(v) && v >= 0.0)) {
      throw std::invalid_argument(std::string(name) + " must be a finite number >= 0, got " +
                                  formatNumber(v));
    }
  }
  if (!(std::isfinite(c.prediction_rotation) && c.prediction_rotation >= 0.0 &&
        c.prediction_rotation <= 1.0)) {
    throw std::invalid_argument("prediction_rotation must be in [0, 1], got " +
                                formatNumber(c.prediction_rotation));
  }
  if (!(std::isfinite(c.min_support) && c.min_support >= 0.0 && c.min_support <= 1.0)) {
    throw std::invalid_argument("min_support must be in [0, 1], got " +
                                formatNumber(c.min_support));
  }
  if (!(std::isfinite(c.hypothesis_step_deg) && c.hypothesis_step_deg > 0.0 &&
        c.hypothesis_step_deg <= 90.0)) {
    throw std::invalid_argument("hypothesis_step_deg must be in (0, 90], got " +
                                formatNumber(c.hypothesis_step_deg));
  }
  if (c.hypothesis_count < 1 || c.hypothesis_count > 16) {
    throw std::invalid_argument("hypothesis_count must be in 1..16, got " +
                                std::to_string(c.hypothesis_count));
  }
  if (c.min_points < 1) {
    throw std::invalid_argument("min_points must be >= 1, got " + std::to_string(c.min_points));
  }
  if (c.max_iterations < 1) {
    throw std::invalid_argument("max_iterations must be >= 1, got " +
                                std::to_string(c.max_iterations));
  }
  return c;
}

/// A size in a message: plain decimals where they are short (`100`, not formatNumber's `1e+02`).
std::string decimal(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return std::strtod(buf, nullptr) == v && std::strchr(buf, 'e') == nullptr ? buf : formatNumber(v);
}

PointToPointIcpParams icpParams(const LidarOdometryConfig& c, double threshold,
                                double convergence) {
  PointToPointIcpParams p;
  p.threshold = threshold;
  p.max_iterations = c.max_iterations;
  p.convergence = convergence;
  p.degeneracy_ratio = c.degeneracy_ratio;
  p.threads = c.threads;
  return p;
}

/// The last motion with its rotation scaled by `share` (about the same axis).
Eigen::Isometry3d predictedMotion(const Eigen::Isometry3d& velocity, double share) {
  if (share == 1.0) return velocity;
  Eigen::AngleAxisd aa(velocity.linear());
  aa.angle() *= share;
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = aa.toRotationMatrix();
  m.translation() = velocity.translation();
  return m;
}

bool finitePoint(const pcl::PointXYZ& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}
bool finitePoint(const Eigen::Vector3d& p) { return p.allFinite(); }

}  // namespace

LidarOdometry::LidarOdometry(const LidarOdometryConfig& config)
    : config_(validated(config)),
      map_(config.voxel_size, config.max_points_per_voxel),
      threshold_(config.initial_threshold, config.min_threshold, config.min_deviation,
                 config.max_range),
      coarse_map_(config.coarse_voxel_size > 0.0 ? config.coarse_voxel_size : 1.0,
                  config.max_points_per_voxel),
      coarse_threshold_(config.initial_threshold, config.min_threshold, config.min_deviation,
                        config.max_range) {}

void LidarOdometry::reset() {
  map_.clear();
  threshold_ = AdaptiveThreshold(config_.initial_threshold, config_.min_threshold,
                                 config_.min_deviation, config_.max_range);
  coarse_map_.clear();
  coarse_threshold_ = threshold_;
  poses_.clear();
}

std::vector<Eigen::Vector3d> toPoints3d(const pcl::PointCloud<pcl::PointXYZ>& scan) {
  std::vector<Eigen::Vector3d> out(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) out[i] = scan[i].getVector3fMap().cast<double>();
  return out;
}

OdometryResult LidarOdometry::registerFrame(const pcl::PointCloud<pcl::PointXYZ>& scan,
                                            const std::vector<double>& times,
                                            const std::string& name) {
  return registerScan(scan, times, name);
}

OdometryResult LidarOdometry::registerFrame(const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<double>& times,
                                            const std::string& name) {
  return registerScan(points, times, name);
}

template <class Scan>
OdometryResult LidarOdometry::registerScan(const Scan& points, const std::vector<double>& times,
                                           const std::string& name) {
  const std::string label = name.empty() ? "frame " + std::to_string(poses_.size()) : name;
  const bool deskew = config_.deskew && poses_.size() >= 2;
  if (config_.deskew && times.size() != points.size()) {
    throw std::invalid_argument(label + ": deskew needs one time per point, got " +
                                std::to_string(times.size()) + " for " +
                                std::to_string(points.size()) + " points");
  }
  if (config_.deskew) {
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (!std::isfinite(times[i]) && finitePoint(points[i]))
        throw std::invalid_argument(label + ": the time of point " + std::to_string(i) +
                                    " is not finite (" + formatNumber(times[i]) + ")");
    }
  }
  OdometryResult res;
  res.points_in = points.size();
  if (points.empty()) throw InputError(label + ": empty scan (no points)");
  // Motion of the last frame: the constant-velocity model for the prediction and the deskew.
  Eigen::Isometry3d velocity = Eigen::Isometry3d::Identity();
  if (poses_.size() >= 2) {
    velocity.matrix() = poses_[poses_.size() - 2].matrix().inverse() * poses_.back().matrix();
  }
  res.points_used = prepareFrame(points, times, deskew, velocity, label);
  res.points_source = source_.size();
  if (poses_.empty()) {  // the first scan defines the world
    res.pose = res.prediction = Eigen::Isometry3d::Identity();
  } else {
    alignFrame(velocity, res.points_used, label, res);
  }
  // Keep the rotation orthonormal over long runs.
  res.pose.linear() = Eigen::Quaterniond(res.pose.linear()).normalized().toRotationMatrix();
  poses_.push_back(res.pose);
  addFrameToMaps(res.pose);
  return res;
}

template <class Scan>
std::size_t LidarOdometry::prepareFrame(const Scan& points, const std::vector<double>& times,
                                        bool deskew, const Eigen::Isometry3d& velocity,
                                        const std::string& label) {
  // Range window and the first downsampling in one pass; the deskew's times follow the points.
  const RangeWindowCounts counts =
      downsampleInRange(points, config_.min_range, config_.max_range, 0.5 * config_.voxel_size,
                        frame_, deskew ? &first_idx_ : nullptr);
  if (counts.finite == 0) {
    throw InputError(label + ": no finite point among " + std::to_string(points.size()));
  }
  if (counts.in_range == 0) {
    throw InputError(label + ": no point between min_range " + formatNumber(config_.min_range) +
                     " and max_range " + formatNumber(config_.max_range) + " m");
  }
  if (counts.in_range < static_cast<std::size_t>(config_.min_points)) {
    throw InputError(label + ": " + std::to_string(counts.in_range) +
                     " point(s) between min_range " + formatNumber(config_.min_range) +
                     " and max_range " + formatNumber(config_.max_range) + " m, at least " +
                     std::to_string(config_.min_points) + " needed to register a frame");
  }
  if (deskew) {
    std::vector<double> t(first_idx_.size());
    for (std::size_t i = 0; i < first_idx_.size(); ++i) {
      t[i] = times[static_cast<std::size_t>(first_idx_[i])];
    }
    frame_ = deskewScan(frame_, t, velocity);
  }
  voxelDownsample(frame_, 1.5 * config_.voxel_size, source_);
  if (config_.coarse_voxel_size > 0.0) {
    voxelDownsample(frame_, 0.5 * config_.coarse_voxel_size, coarse_frame_);
    voxelDownsample(coarse_frame_, 1.5 * config_.coarse_voxel_size, coarse_source_);
  }
  return counts.in_range;
}

void LidarOdometry::alignFrame(const Eigen::Isometry3d& velocity, std::size_t in_range,
                               const std::string& label, OdometryResult& res) {
  const bool coarse = config_.coarse_voxel_size > 0.0;
  const Eigen::Isometry3d& last = poses_.back();
  res.prediction = last * predictedMotion(velocity, config_.prediction_rotation);
  Eigen::Isometry3d initial = res.prediction;
  if (coarse) {
    const double threshold = coarse_threshold_.threshold();
    const PointToPointIcpResult c =
        alignWithRecovery(coarse_source_, coarse_map_, initial, &last, threshold, 0.0,
                          config_.convergence, res.restarted);
    Eigen::Isometry3d deviation;
    deviation.matrix() = initial.matrix().inverse() * c.pose.matrix();
    coarse_threshold_.update(deviation);
    initial = c.pose;
    res.coarse_iterations = c.iterations;
  }
  res.coarse = initial;
  res.threshold = threshold_.threshold();
  if (config_.max_threshold > 0.0) res.threshold = std::min(res.threshold, config_.max_threshold);
  // Without a coarse stage the fine one recovers from a bad prediction itself; after one, its
  // guess is already the coarse map's answer.
  PointToPointIcpResult icp =
      alignWithRecovery(source_, map_, initial, coarse ? nullptr : &last, res.threshold,
                        config_.max_threshold, config_.convergence, res.restarted);
  tryHypotheses(velocity, icp, initial, res);
  if (icp.correspondences < kMinOdometryPairs) {
    throw InputError(label + ": the registration paired " + std::to_string(icp.correspondences) +
                     " of its " + std::to_string(source_.size()) +
                     " downsampled points with the local map, at least " +
                     std::to_string(kMinOdometryPairs) + " needed (" + std::to_string(in_range) +
                     " points in range, voxel size " + decimal(config_.voxel_size) +
                     " m): the pose would rest on too few points; a smaller voxel size keeps "
                     "more");
  }
  res.pose = icp.pose;
  res.correspondences = icp.correspondences;
  res.iterations = icp.iterations;
  res.degenerate_directions = icp.degenerate_directions;
  res.eigen_ratio = icp.eigen_ratio;
  Eigen::Isometry3d deviation;  // from the guess the fine ICP started at
  deviation.matrix() = initial.matrix().inverse() * res.pose.matrix();
  threshold_.update(deviation);
}

void LidarOdometry::tryHypotheses(const Eigen::Isometry3d& velocity, PointToPointIcpResult& icp,
                                  Eigen::Isometry3d& start, OdometryResult& res) {
  const double distance =
      config_.support_distance > 0.0 ? config_.support_distance : config_.voxel_size;
  PoseSupport best = poseSupport(source_, map_, icp.pose, distance);
  res.support = best.fraction(source_.size());
  if (!(res.support < config_.min_support) || poses_.size() < 2) return;
  const std::vector<Eigen::Isometry3d> starts =
      motionHypotheses(poses_.back(), velocity, config_.hypothesis_step_deg);
  // Rank the other starts by their support as they are, then register the best few.
  std::vector<std::pair<PoseSupport, std::size_t>> ranked;
  for (std::size_t k = 1; k < starts.size(); ++k) {
    ranked.emplace_back(poseSupport(source_, map_, starts[k], distance), k);
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first.betterThan(b.first); });
  ranked.resize(std::min(ranked.size(), static_cast<std::size_t>(config_.hypothesis_count)));
  res.hypothesis = 0;
  for (const auto& [support, k] : ranked) {
    const double threshold = std::max(res.threshold, distance);
    PointToPointIcpResult r = alignPointToPoint(
        source_, map_, starts[k], icpParams(config_, threshold, config_.convergence), &icp_);
    if (config_.fine_threshold > 0.0 && threshold > config_.fine_threshold) {
      const int before = r.iterations;
      r = alignPointToPoint(source_, map_, r.pose,
                            icpParams(config_, config_.fine_threshold, config_.convergence), &icp_);
      r.iterations += before;
    }
    const PoseSupport s = poseSupport(source_, map_, r.pose, distance);
    if (s.betterThan(best)) {
      r.iterations += icp.iterations;
      icp = r;
      best = s;
      start = starts[k];
      res.hypothesis = static_cast<int>(k);
    } else {
      icp.iterations += r.iterations;
    }
  }
  res.support = best.fraction(source_.size());
}

void LidarOdometry::addFrameToMaps(const Eigen::Isometry3d& pose) {
  for (Eigen::Vector3d& p : frame_) p = pose * p;
  map_.add(frame_);
  map_.removeFar(pose.translation(), config_.max_range);
  if (config_.coarse_voxel_size > 0.0) {
    for (Eigen::Vector3d& p : coarse_frame_) p = pose * p;
    coarse_map_.add(coarse_frame_);
    coarse_map_.removeFar(pose.translation(), config_.max_range);
  }
}

PointToPointIcpResult LidarOdometry::alignWithRecovery(const std::vector<Eigen::Vector3d>& source,
                                                       const VoxelHashMap& map,
                                                       const Eigen::Isometry3d& initial,
                                                       const Eigen::Isometry3d* last,
                                                       double threshold, double cap,
                                                       double convergence, bool& restarted) {
  PointToPointIcpResult icp =
      alignPointToPoint(source, map, initial, icpParams(config_, threshold, convergence), &icp_);
  const double need = config_.min_inlier_fraction * static_cast<double>(source.size());
  if (last && static_cast<double>(icp.correspondences) < need && poses_.size() >= 2) {
    // The prediction is off by more than the threshold (an abrupt stop, a reversal, a
    // jolt): start again from the last pose with the initial, wide threshold.
    double wide = std::max(3.0 * config_.initial_threshold, threshold);
    if (cap > 0.0) wide = std::min(wide, cap);
    PointToPointIcpResult again =
        alignPointToPoint(source, map, *last, icpParams(config_, wide, convergence), &icp_);
    // Compare both at the same (narrow) threshold.
    const PointToPointIcpResult check = alignPointToPoint(
        source, map, again.pose, icpParams(config_, threshold, convergence), &icp_);
    if (check.correspondences > icp.correspondences) {
      icp = check;
      icp.iterations += again.iterations;
      restarted = true;
    }
  }
  if (config_.fine_threshold > 0.0 && threshold > config_.fine_threshold) {
    const int before = icp.iterations;
    icp = alignPointToPoint(source, map, icp.pose,
                            icpParams(config_, config_.fine_threshold, convergence), &icp_);
    icp.iterations += before;
  }
  return icp;
}

}  // namespace metricmap
