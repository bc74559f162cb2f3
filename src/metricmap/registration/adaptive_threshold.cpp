#include "metricmap/registration/adaptive_threshold.h"

#include <algorithm>
#include <cmath>

namespace metricmap {

double AdaptiveThreshold::deviationMetres(const Eigen::Isometry3d& d, double lever) {
  const double c = std::clamp((d.linear().trace() - 1.0) / 2.0, -1.0, 1.0);
  const double angle = std::acos(c);
  return d.translation().norm() + 2.0 * lever * std::sin(angle / 2.0);
}

void AdaptiveThreshold::update(const Eigen::Isometry3d& deviation) {
  const double e = std::max(deviationMetres(deviation, lever_), min_deviation_);
  sum_sq_ += e * e;
  ++samples_;
}

double AdaptiveThreshold::threshold() const {
  const double sigma =
      samples_ == 0 ? initial_sigma_ : std::sqrt(sum_sq_ / static_cast<double>(samples_));
  return std::max(3.0 * sigma, min_threshold_);
}

}  // namespace metricmap
