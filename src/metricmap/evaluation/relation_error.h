#pragma once
/// \file relation_error.h
/// \brief The relation-based metric of Kümmerle et al., "On measuring the accuracy of SLAM
/// algorithms" (Autonomous Robots 27(4), 2009): for every given relation delta*_ij between the
/// poses at two stamps, the error of the estimated relation delta_ij = P_i^-1 P_j is
/// delta_ij (-) delta*_ij = delta*_ij^-1 delta_ij; reported as mean +/- std of its translation
/// (m), squared translation (m^2), rotation angle (deg) and squared angle (deg^2).

#include <cstddef>
#include <optional>
#include <vector>

#include "metricmap/common/pose_relation.h"
#include "metricmap/common/trajectory.h"
#include "metricmap/evaluation/error_statistics.h"

namespace metricmap {

/// \brief The metric over the relations whose two stamps were found in the estimate.
struct RelationError {
  std::size_t used = 0;
  std::vector<std::size_t> skipped;  ///< indices of the relations not found
  /// \brief Relation stamps without an estimated pose within max_time_diff, placed by the
  /// odometry from the nearest estimated pose (counted once per stamp).
  std::size_t interpolated = 0;
  std::vector<std::size_t> used_relations;  ///< per used relation, its index in the input
  std::vector<double> translation;          ///< per used relation, metres
  std::vector<double> rotation_deg;         ///< per used relation, degrees
  MeanAndStd translation_abs;               ///< m
  MeanAndStd translation_sq;                ///< m^2
  MeanAndStd rotation_abs_deg;              ///< deg
  MeanAndStd rotation_sq_deg;               ///< deg^2
};

/// \brief The metric of `estimate` over `relations`.
///
/// Each relation's stamps are looked up in the estimate's stamps: the nearest one is used when
/// it is within `max_time_diff` seconds. Otherwise, as the benchmark's metricEvaluator does,
/// when `odometry` (the log's raw odometry, with stamps) is given, the pose is the nearest
/// estimated pose P(t_n) moved by the odometry's motion from t_n to the stamp:
/// P(t) = P(t_n) O(t_n)^-1 O(t), O interpolated between its two nearest stamps (linear in
/// translation, slerp in rotation); a stamp outside the odometry's span by more than
/// max_time_diff, or a relation without odometry, is skipped and counted.
/// Standard deviations divide by n - 1.
/// Stamps need not increase (raw logs step back): they are searched in sorted order, the first
/// of equal stamps in the estimate's order winning.
/// \throws std::invalid_argument when the estimate (or the odometry) has no stamps or one is not
/// finite; InputError when no relation could be measured (both stamps found)
RelationError relationError(const Trajectory& estimate, const std::vector<PoseRelation>& relations,
                            double max_time_diff = 0.01, const Trajectory* odometry = nullptr);

/// \brief The pose of `trajectory` at `t`: interpolated between the two stamps around it
/// (linear in translation, slerp in rotation), or the end pose when t is beyond an end by at
/// most `max_extrapolation` seconds; nullopt further out. Stamps need not be sorted.
/// \throws std::invalid_argument when the trajectory has no stamps or one is not finite
std::optional<Eigen::Isometry3d> poseAtStamp(const Trajectory& trajectory, double t,
                                             double max_extrapolation);

}  // namespace metricmap
