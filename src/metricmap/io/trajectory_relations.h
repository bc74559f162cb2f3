#pragma once
/// \file trajectory_relations.h
/// \brief Relations files of the Freiburg SLAM benchmark (Kümmerle et al., "On measuring the
/// accuracy of SLAM algorithms", Autonomous Robots 27(4), 2009), as its metricEvaluator and
/// Cartographer's compute_relations_metrics read them.

#include <string>
#include <vector>

#include "metricmap/common/pose_relation.h"

namespace metricmap {

/// \brief A relations file: one relation per line, "t1 t2 x y z roll pitch yaw" (stamps in
/// seconds, translation in metres, angles in radians; rotation = Rz(yaw) * Ry(pitch) *
/// Rx(roll)). Blank lines and '#' comments are skipped; every number goes through
/// parseFiniteDouble; what is allocated is bounded by the file's size.
/// \throws InputError naming the file and line: not 8 values, a bad number, a translation
/// beyond kMaxTranslation, no relation at all; CapacityError when it does not fit the budget
std::vector<PoseRelation> readRelations(const std::string& path);

}  // namespace metricmap
