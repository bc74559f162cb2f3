#include "metricmap/registration/motion_hypotheses.h"

#include <cmath>

namespace metricmap {

PoseSupport poseSupport(const std::vector<Eigen::Vector3d>& source, const VoxelHashMap& map,
                        const Eigen::Isometry3d& pose, double threshold) {
  PoseSupport s;
  VoxelHashMap::Neighbourhood hood;
  Eigen::Vector3d q;
  for (const Eigen::Vector3d& p : source) {
    const Eigen::Vector3d w = pose * p;
    if (!map.nearestCached(w, threshold, hood, q)) continue;
    ++s.inliers;
    s.sum_sq += (w - q).squaredNorm();
  }
  return s;
}

std::vector<Eigen::Isometry3d> motionHypotheses(const Eigen::Isometry3d& last,
                                                const Eigen::Isometry3d& velocity,
                                                double step_deg) {
  Eigen::Isometry3d straight = Eigen::Isometry3d::Identity();
  straight.translation() = velocity.translation();
  std::vector<Eigen::Isometry3d> h = {last * velocity, last * straight, last};
  const double s = step_deg * M_PI / 180.0;
  auto turned = [&](double angle, const Eigen::Vector3d& axis) {
    Eigen::Isometry3d r = Eigen::Isometry3d::Identity();
    r.linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    return last * straight * r;
  };
  for (double a : {s, -s, 2 * s, -2 * s}) h.push_back(turned(a, Eigen::Vector3d::UnitZ()));
  for (double a : {s, -s}) {
    h.push_back(turned(a, Eigen::Vector3d::UnitX()));
    h.push_back(turned(a, Eigen::Vector3d::UnitY()));
  }
  return h;
}

}  // namespace metricmap
