#include "metricmap/evaluation/step_failures.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "metricmap/common/format_number.h"

namespace metricmap {

StepFailures findStepFailures(const RelativeError& rpe, const StepFailureLimits& limits) {
  for (auto [v, name] : {std::pair{limits.max_translation, "step error limit (translation)"},
                         std::pair{limits.max_rotation_deg, "step error limit (rotation)"}}) {
    if (!(std::isfinite(v) && v > 0.0)) {
      throw std::invalid_argument(std::string(name) + " must be a finite number > 0, got " +
                                  formatNumber(v));
    }
  }
  StepFailures f;
  f.limits = limits;
  f.steps = rpe.translation.size();
  for (std::size_t i = 0; i < f.steps; ++i) {
    if (rpe.translation[i] > limits.max_translation ||
        rpe.rotation_deg[i] > limits.max_rotation_deg) {
      f.failed.push_back(i);
    }
  }
  return f;
}

}  // namespace metricmap
