#include "metricmap/evaluation/relative_error.h"

#include <stdexcept>
#include <string>

#include "metricmap/evaluation/rotation_angle.h"

namespace metricmap {

RelativeError relativeError(const std::vector<Eigen::Isometry3d>& estimate,
                            const std::vector<Eigen::Isometry3d>& reference) {
  if (estimate.size() != reference.size()) {
    throw std::invalid_argument("RPE: " + std::to_string(estimate.size()) + " estimated and " +
                                std::to_string(reference.size()) + " reference poses");
  }
  RelativeError e;
  for (std::size_t i = 0; i + 1 < estimate.size(); ++i) {
    const Eigen::Isometry3d q = reference[i].inverse() * reference[i + 1];
    const Eigen::Isometry3d p = estimate[i].inverse() * estimate[i + 1];
    const Eigen::Isometry3d err = q.inverse() * p;
    e.translation.push_back(err.translation().norm());
    e.rotation_deg.push_back(rotationAngleDeg(err.linear()));
  }
  e.translation_stats = summarizeErrors(e.translation);
  e.rotation_stats = summarizeErrors(e.rotation_deg);
  return e;
}

}  // namespace metricmap
