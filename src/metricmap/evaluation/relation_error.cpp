#include "metricmap/evaluation/relation_error.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "metricmap/evaluation/pose_pairing.h"
#include "metricmap/evaluation/rotation_angle.h"

namespace metricmap {

RelationError relationError(const Trajectory& estimate, const std::vector<PoseRelation>& relations,
                            double max_time_diff) {
  if (!estimate.hasStamps()) {
    throw std::invalid_argument("the relation metric needs an estimate with time stamps");
  }
  if (estimate.stamps.size() != estimate.size())
    throw std::invalid_argument("the estimate has " + std::to_string(estimate.stamps.size()) +
                                " stamps for " + std::to_string(estimate.size()) + " poses");
  // Stamps in the order the estimate gives them (raw logs step back): looked up sorted.
  std::vector<std::size_t> order(estimate.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return estimate.stamps[a] < estimate.stamps[b];
  });
  std::vector<double> sorted(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    sorted[k] = estimate.stamps[order[k]];
    if (!std::isfinite(sorted[k]))
      throw std::invalid_argument("the estimate has a stamp that is not finite");
  }
  RelationError e;
  std::vector<double> t_sq, r_sq;
  for (std::size_t k = 0; k < relations.size(); ++k) {
    const PoseRelation& r = relations[k];
    std::size_t i = nearestStamp(sorted, r.stamp1, max_time_diff);
    std::size_t j = nearestStamp(sorted, r.stamp2, max_time_diff);
    if (i == estimate.size() || j == estimate.size()) {
      e.skipped.push_back(k);
      continue;
    }
    i = order[i];
    j = order[j];
    const Eigen::Isometry3d delta = estimate.poses[i].inverse() * estimate.poses[j];
    const Eigen::Isometry3d err = r.relative.inverse() * delta;
    e.translation.push_back(err.translation().norm());
    e.rotation_deg.push_back(rotationAngleDeg(err.linear()));
    t_sq.push_back(e.translation.back() * e.translation.back());
    r_sq.push_back(e.rotation_deg.back() * e.rotation_deg.back());
  }
  e.used = e.translation.size();
  e.translation_abs = meanAndSampleStd(e.translation);
  e.translation_sq = meanAndSampleStd(t_sq);
  e.rotation_abs_deg = meanAndSampleStd(e.rotation_deg);
  e.rotation_sq_deg = meanAndSampleStd(r_sq);
  return e;
}

}  // namespace metricmap
