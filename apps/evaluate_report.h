#pragma once
/// \file evaluate_report.h
/// \brief The reports of `metricmap evaluate`: against a reference trajectory, or the relation
/// metric; JSON or text tables.

#include <cstddef>
#include <string>
#include <vector>

#include "metricmap/common/pose_relation.h"
#include "metricmap/evaluation/relation_error.h"
#include "metricmap/evaluation/trajectory_evaluation.h"
#include "metricmap/io/trajectory.h"

namespace metricmap::cli {

/// \brief A trajectory file as read, with the form it was read in.
struct LoadedTrajectory {
  std::string path;
  Trajectory trajectory;
  TrajectoryFormat format = TrajectoryFormat::Auto;
};

/// \brief A number as the reports print it (printf %.6g).
std::string num(double v);

/// \brief ATE, RPE and KITTI drift of `est` against `ref` (`format` json, else text; the text
/// has the RPE of every frame with `per_frame`).
std::string referenceReport(const LoadedTrajectory& est, const LoadedTrajectory& ref,
                            const TrajectoryEvaluation& ev, const EvaluationConfig& config,
                            bool per_frame, const std::string& format);

/// \brief What the relation metric ran on, besides the estimate.
struct RelationsInput {
  std::string path;  ///< the relations file
  const std::vector<PoseRelation>* relations = nullptr;
  double max_time_diff = 0.0;
  std::string odometry;  ///< the odometry file, "" without
};

/// \brief How many relations the reports list as the worst (by translation, by rotation).
inline constexpr std::size_t kWorstRelations = 10;

/// \brief The relation metric of `est` (`format` json, else text): mean and std, the worst
/// relations with their stamps; the JSON also has every used relation's error (per_relation).
std::string relationsReport(const LoadedTrajectory& est, const RelationsInput& in,
                            const RelationError& e, const std::string& format);

}  // namespace metricmap::cli
