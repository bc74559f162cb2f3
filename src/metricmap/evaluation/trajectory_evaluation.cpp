#include "metricmap/evaluation/trajectory_evaluation.h"

namespace metricmap {

TrajectoryEvaluation evaluateTrajectory(const Trajectory& estimate, const Trajectory& reference,
                                        const EvaluationConfig& config) {
  TrajectoryEvaluation ev;
  ev.pairs = pairPoses(estimate, reference, config.max_time_diff);
  std::vector<Eigen::Isometry3d> est, ref;
  est.reserve(ev.pairs.size());
  ref.reserve(ev.pairs.size());
  for (std::size_t k = 0; k < ev.pairs.size(); ++k) {
    est.push_back(estimate.poses[ev.pairs.estimate[k]]);
    ref.push_back(reference.poses[ev.pairs.reference[k]]);
  }
  ev.alignment_mode = config.alignment;
  ev.alignment = alignPositions(est, ref, config.alignment);
  const std::vector<Eigen::Isometry3d> aligned = applyAlignment(ev.alignment, est);
  ev.ate = absoluteError(aligned, ref);
  ev.rpe = relativeError(aligned, ref);
  ev.steps = findStepFailures(ev.rpe, config.steps);
  ev.drift = kittiDrift(est, ref, config.drift);
  return ev;
}

}  // namespace metricmap
