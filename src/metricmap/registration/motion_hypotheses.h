#pragma once
/// \file motion_hypotheses.h
/// \brief Where a scan may be when the constant-velocity prediction is wrong, and how well a
/// pose fits the local map. A balancing robot (a Segway) pitches and yaws by several degrees
/// between keyframes, back and forth: its last motion predicts the next one badly, and an ICP
/// started there can converge to a wrong minimum. The odometry then starts again from the
/// motions a robot allows and keeps the best-supported result.

#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/registration/voxel_hash_map.h"

namespace metricmap {

/// \brief How well a pose fits the map: source points with a map point within a threshold.
struct PoseSupport {
  std::size_t inliers = 0;
  double sum_sq = 0.0;  ///< sum of the inliers' squared distances (m^2)
  /// \brief Inliers / source points (0 for an empty source).
  double fraction(std::size_t source_size) const {
    return source_size ? static_cast<double>(inliers) / static_cast<double>(source_size) : 0.0;
  }
  /// \brief More inliers wins; equal counts: the smaller squared distances.
  bool betterThan(const PoseSupport& o) const {
    return inliers != o.inliers ? inliers > o.inliers : sum_sq < o.sum_sq;
  }
};

/// \brief The support of `pose` (sensor -> map) for `source` (sensor frame) at `threshold`.
PoseSupport poseSupport(const std::vector<Eigen::Vector3d>& source, const VoxelHashMap& map,
                        const Eigen::Isometry3d& pose, double threshold);

/// \brief Starting poses when the prediction failed, given the last pose and the last motion
/// (`velocity`, last-but-one^-1 last): the constant-velocity guess, its translation without
/// its rotation, zero motion, then the translation-only guess turned by +-`step_deg` and
/// +-2 `step_deg` about the sensor's z axis and by +-`step_deg` about its x and y axes.
std::vector<Eigen::Isometry3d> motionHypotheses(const Eigen::Isometry3d& last,
                                                const Eigen::Isometry3d& velocity, double step_deg);

}  // namespace metricmap
