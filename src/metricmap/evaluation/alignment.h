#pragma once
/// \file alignment.h
/// \brief Umeyama alignment of estimated positions to reference positions, rigid (SE(3)) or
/// similarity (Sim(3)), as evo does it (`evo_ape --align [--correct_scale]`).

#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace metricmap {

/// \brief none: the estimate as given; rigid: rotation + translation; similarity: and a scale.
enum class AlignmentMode { None, Rigid, Similarity };

/// \brief "none" | "rigid" | "sim". \throws std::invalid_argument naming the text
AlignmentMode parseAlignmentMode(const std::string& name);

/// \brief "none", "rigid" or "sim".
const char* alignmentModeName(AlignmentMode mode);

/// \brief x -> scale * rotation * x + translation, applied to an estimate's positions; its
/// orientations turn by `rotation` (evo: traj.scale(s), then traj.transform(R, t)).
struct Alignment {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;

  /// \brief The pose moved by the alignment (rotation R_a R, position s R_a t + t_a).
  Eigen::Isometry3d apply(const Eigen::Isometry3d& pose) const;
};

/// \brief The alignment minimising sum |s R p_i + t - q_i|^2 over the estimate's positions p_i
/// and the reference's q_i (Eigen::umeyama; s = 1 unless `mode` is Similarity; identity for
/// None).
/// \throws std::invalid_argument when the counts differ or are zero, or (Rigid, Similarity)
/// when the positions' cross-covariance has rank below 2 (collinear or coinciding positions:
/// the rotation is not determined; evo refuses these too), or is nearly so: its second singular
/// value below 1e-8 of the first (a spread across the path below 1e-4 of the spread along), or
/// below a quarter of sqrt(λ2(estimate) λ2(reference)), the second variances of the two position
/// sets (what lies across the path is not shared: noise). The rotation about the path would be
/// set by noise (a straight path aligned with a 150-degree turn); no fallback is guessed.
Alignment alignPositions(const std::vector<Eigen::Isometry3d>& estimate,
                         const std::vector<Eigen::Isometry3d>& reference, AlignmentMode mode);

/// \brief Every pose moved by the alignment.
std::vector<Eigen::Isometry3d> applyAlignment(const Alignment& alignment,
                                              const std::vector<Eigen::Isometry3d>& poses);

}  // namespace metricmap
