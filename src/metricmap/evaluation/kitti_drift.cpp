#include "metricmap/evaluation/kitti_drift.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

namespace metricmap {

KittiDrift kittiDrift(const std::vector<Eigen::Isometry3d>& estimate,
                      const std::vector<Eigen::Isometry3d>& reference,
                      const KittiDriftConfig& config) {
  if (estimate.size() != reference.size()) {
    throw std::invalid_argument("KITTI drift: " + std::to_string(estimate.size()) +
                                " estimated and " + std::to_string(reference.size()) +
                                " reference poses");
  }
  if (config.step == 0) throw std::invalid_argument("KITTI drift: step must be > 0");
  for (double l : config.lengths) {
    if (!(l > 0.0)) throw std::invalid_argument("KITTI drift: segment lengths must be > 0");
  }
  KittiDrift drift;
  const std::size_t n = reference.size();
  std::vector<double> dist(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) {
    dist[i] = dist[i - 1] + (reference[i].translation() - reference[i - 1].translation()).norm();
  }
  drift.path_length = n ? dist.back() : 0.0;
  for (double l : config.lengths) drift.lengths.push_back(KittiDriftLength{l, 0, 0.0, 0.0});
  constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
  for (std::size_t first = 0; first < n; first += config.step) {
    for (KittiDriftLength& len : drift.lengths) {
      // The first frame farther than first's distance + length (dist never decreases).
      const auto it = std::upper_bound(dist.begin() + static_cast<std::ptrdiff_t>(first),
                                       dist.end(), dist[first] + len.length);
      if (it == dist.end()) continue;
      const std::size_t last = static_cast<std::size_t>(it - dist.begin());
      // As the devkit: general 4x4 inverses (pose files are orthonormal only to ~1e-7) and
      // the angle from the trace alone.
      const Eigen::Matrix4d gt = reference[first].matrix().inverse() * reference[last].matrix();
      const Eigen::Matrix4d est = estimate[first].matrix().inverse() * estimate[last].matrix();
      const Eigen::Matrix4d err = est.inverse() * gt;
      const double t_err = err.topRightCorner<3, 1>().norm() / len.length;
      const double cos_angle =
          std::clamp(0.5 * (err.topLeftCorner<3, 3>().trace() - 1.0), -1.0, 1.0);
      const double r_err = std::acos(cos_angle) / len.length;
      ++len.segments;
      len.translation_percent += t_err;
      len.rotation_deg_per_m += r_err;
      ++drift.segments;
      drift.translation_percent += t_err;
      drift.rotation_deg_per_m += r_err;
    }
  }
  auto average = [&](std::size_t count, double& t, double& r) {
    if (count == 0) return;
    t = 100.0 * t / static_cast<double>(count);
    r = kDegPerRad * r / static_cast<double>(count);
  };
  for (KittiDriftLength& len : drift.lengths)
    average(len.segments, len.translation_percent, len.rotation_deg_per_m);
  average(drift.segments, drift.translation_percent, drift.rotation_deg_per_m);
  return drift;
}

}  // namespace metricmap
