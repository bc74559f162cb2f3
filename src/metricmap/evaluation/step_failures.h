#pragma once
/// \file step_failures.h
/// \brief Steps of an odometry that failed: the per-frame relative pose errors (RPE, delta 1
/// frame) whose translation exceeds a distance or whose rotation exceeds an angle. A median RPE
/// hides a few broken steps; their count is what decides whether a map comes out usable.

#include <cstddef>
#include <vector>

#include "metricmap/evaluation/relative_error.h"

namespace metricmap {

/// \brief Limits a step's error may reach before it counts as failed.
struct StepFailureLimits {
  double max_translation = 0.3;   ///< metres; > 0
  double max_rotation_deg = 3.0;  ///< degrees; > 0
};

/// \brief The failed steps (entry i: from pose i to pose i + 1, as RelativeError's).
struct StepFailures {
  StepFailureLimits limits;
  std::size_t steps = 0;            ///< steps checked
  std::vector<std::size_t> failed;  ///< indices i of the failed steps, increasing
};

/// \brief The steps of `rpe` whose translation error is above `limits.max_translation` or whose
/// rotation error is above `limits.max_rotation_deg`.
/// \throws std::invalid_argument when a limit is not a finite number > 0
StepFailures findStepFailures(const RelativeError& rpe, const StepFailureLimits& limits = {});

}  // namespace metricmap
