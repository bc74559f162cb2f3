#pragma once
/// \file relation_error.h
/// \brief The relation-based metric of Kümmerle et al., "On measuring the accuracy of SLAM
/// algorithms" (Autonomous Robots 27(4), 2009): for every given relation delta*_ij between the
/// poses at two stamps, the error of the estimated relation delta_ij = P_i^-1 P_j is
/// delta_ij (-) delta*_ij = delta*_ij^-1 delta_ij; reported as mean +/- std of its translation
/// (m), squared translation (m^2), rotation angle (deg) and squared angle (deg^2).

#include <cstddef>
#include <vector>

#include "metricmap/evaluation/error_statistics.h"
#include "metricmap/evaluation/pose_relation.h"
#include "metricmap/evaluation/trajectory.h"

namespace metricmap {

/// \brief The metric over the relations whose two stamps were found in the estimate.
struct RelationError {
  std::size_t used = 0;
  std::vector<std::size_t> skipped;  ///< indices of the relations not found
  std::vector<double> translation;   ///< per used relation, metres
  std::vector<double> rotation_deg;  ///< per used relation, degrees
  MeanAndStd translation_abs;        ///< m
  MeanAndStd translation_sq;         ///< m^2
  MeanAndStd rotation_abs_deg;       ///< deg
  MeanAndStd rotation_sq_deg;        ///< deg^2
};

/// \brief The metric of `estimate` over `relations`.
///
/// Each relation's stamps are looked up in the estimate's stamps: the nearest one is used when
/// it is within `max_time_diff` seconds (a relation whose stamp has none is skipped and
/// counted; the benchmark's metricEvaluator looks within 0.1 s and otherwise interpolates
/// odometry, which an estimate does not have). Standard deviations divide by n - 1.
/// Stamps need not increase (raw logs step back): they are searched in sorted order, the first
/// of equal stamps in the estimate's order winning.
/// \throws std::invalid_argument when the estimate has no stamps or one is not finite
RelationError relationError(const Trajectory& estimate, const std::vector<PoseRelation>& relations,
                            double max_time_diff = 0.01);

}  // namespace metricmap
