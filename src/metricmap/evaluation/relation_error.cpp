#include "metricmap/evaluation/relation_error.h"

#include <stdexcept>

#include "metricmap/evaluation/pose_pairing.h"
#include "metricmap/evaluation/rotation_angle.h"

namespace metricmap {

RelationError relationError(const Trajectory& estimate, const std::vector<PoseRelation>& relations,
                            double max_time_diff) {
  if (!estimate.hasStamps()) {
    throw std::invalid_argument("the relation metric needs an estimate with time stamps");
  }
  requireIncreasingStamps(estimate, "estimate");
  RelationError e;
  std::vector<double> t_sq, r_sq;
  for (std::size_t k = 0; k < relations.size(); ++k) {
    const PoseRelation& r = relations[k];
    const std::size_t i = nearestStamp(estimate.stamps, r.stamp1, max_time_diff);
    const std::size_t j = nearestStamp(estimate.stamps, r.stamp2, max_time_diff);
    if (i == estimate.size() || j == estimate.size()) {
      e.skipped.push_back(k);
      continue;
    }
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
