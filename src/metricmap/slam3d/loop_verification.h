#pragma once
/// \file loop_verification.h
/// \brief Geometric verification of a loop candidate: the query's local map is aligned to the
/// candidate's by the toolkit's robust point-to-point ICP (coarse to fine thresholds) from an
/// initial guess, then accepted only when enough of its points, and enough of its points above
/// the ground, lie on the candidate's map, and no direction of the alignment is degenerate.
/// Ground points match anywhere on flat ground: the structure overlap is what tells places apart.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace metricmap {

/// \brief Thresholds of the verification.
struct LoopVerificationParams {
  double coarse_threshold = 3.0;  ///< first ICP stage's correspondence distance (m, > 0)
  double fine_threshold = 0.6;    ///< last ICP stage's (m, > 0, <= coarse_threshold)
  double map_voxel = 1.0;         ///< voxel of the candidate's map (m, > 0)
  double overlap_distance = 0.4;  ///< a point overlaps when a map point is this close (m, > 0)
  double min_overlap = 0.5;       ///< share of the query's points that must overlap ([0, 1])
  double min_structure_overlap = 0.35;  ///< share of its points above the ground ([0, 1])
  double ground_margin = 0.5;  ///< points this far above the local ground count as structure (m)
  /// \brief The correction from the initial guess may be at most this far (m, > 0): a match
  /// that runs far along a corridor is not trusted.
  double max_correction = 8.0;
};

/// \brief \throws std::invalid_argument naming the first bad field
void validateLoopVerificationParams(const LoopVerificationParams& params);

/// \brief What the verification found.
struct LoopVerification {
  bool accepted = false;
  /// \brief Query frame -> candidate frame after the alignment.
  Eigen::Isometry3d relation = Eigen::Isometry3d::Identity();
  double overlap = 0.0;            ///< share of the query's points within overlap_distance
  double structure_overlap = 0.0;  ///< the same among the points above the ground
  double rmse = 0.0;               ///< RMS distance of the overlapping points (m)
  int degenerate_directions = 0;
  std::string reason;  ///< why it was rejected ("" when accepted)
};

/// \brief Verify a loop between the query's local map `query` (query frame) and the candidate's
/// `candidate` (candidate frame) from the guess `initial` (query -> candidate).
LoopVerification verifyLoop(const std::vector<Eigen::Vector3f>& query,
                            const std::vector<Eigen::Vector3f>& candidate,
                            const Eigen::Isometry3d& initial, const LoopVerificationParams& params);

}  // namespace metricmap
