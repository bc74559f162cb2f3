#include "metricmap/evaluation/absolute_error.h"

#include <stdexcept>
#include <string>

#include "metricmap/evaluation/rotation_angle.h"

namespace metricmap {

AbsoluteError absoluteError(const std::vector<Eigen::Isometry3d>& estimate,
                            const std::vector<Eigen::Isometry3d>& reference) {
  if (estimate.size() != reference.size()) {
    throw std::invalid_argument("ATE: " + std::to_string(estimate.size()) + " estimated and " +
                                std::to_string(reference.size()) + " reference poses");
  }
  AbsoluteError e;
  e.translation.reserve(estimate.size());
  e.rotation_deg.reserve(estimate.size());
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    e.translation.push_back((estimate[i].translation() - reference[i].translation()).norm());
    e.rotation_deg.push_back(
        rotationAngleDeg(reference[i].linear().transpose() * estimate[i].linear()));
  }
  e.translation_stats = summarizeErrors(e.translation);
  e.rotation_stats = summarizeErrors(e.rotation_deg);
  return e;
}

}  // namespace metricmap
