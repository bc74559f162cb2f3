#pragma once
/// \file trajectory_evaluation.h
/// \brief Everything `metricmap evaluate` reports for an estimate against a reference: the
/// pairing, the alignment, ATE, per-frame RPE and KITTI drift, computed in one call.

#include "metricmap/common/trajectory.h"
#include "metricmap/evaluation/absolute_error.h"
#include "metricmap/evaluation/alignment.h"
#include "metricmap/evaluation/kitti_drift.h"
#include "metricmap/evaluation/pose_pairing.h"
#include "metricmap/evaluation/relative_error.h"
#include "metricmap/evaluation/step_failures.h"

namespace metricmap {

/// \brief How the estimate is compared with the reference.
struct EvaluationConfig {
  AlignmentMode alignment = AlignmentMode::Rigid;
  double max_time_diff = 0.01;  ///< seconds, pairing by stamps (evo's --t_max_diff default)
  KittiDriftConfig drift;
  StepFailureLimits steps;  ///< when a step of the RPE counts as failed
};

/// \brief The metrics, over the paired poses.
struct TrajectoryEvaluation {
  PosePairs pairs;
  AlignmentMode alignment_mode = AlignmentMode::Rigid;
  Alignment alignment;  ///< estimate -> reference frame (identity for None)
  AbsoluteError ate;    ///< of the aligned estimate
  RelativeError rpe;    ///< of the aligned estimate (a similarity scales its steps, as evo)
  KittiDrift drift;     ///< of the estimate as given (as the devkit)
  StepFailures steps;   ///< the RPE's steps beyond config.steps
};

/// \brief Pair (pairPoses), align the paired positions (alignPositions), then ATE and RPE of
/// the aligned estimate, its failed steps and KITTI drift of the paired estimate as given.
/// \throws std::invalid_argument from pairPoses, alignPositions and findStepFailures
TrajectoryEvaluation evaluateTrajectory(const Trajectory& estimate, const Trajectory& reference,
                                        const EvaluationConfig& config = {});

}  // namespace metricmap
