#pragma once
/// \file point_to_point_icp.h
/// \brief Robust point-to-point ICP of a scan against a VoxelHashMap: Gauss-Newton with a
/// Geman-McClure kernel, and degenerate directions held at the initial guess.

#include <vector>

#include <Eigen/Geometry>

#include "metricmap/registration/voxel_hash_map.h"

namespace metricmap {

struct PointToPointIcpParams {
  double threshold = 1.0;          ///< correspondences farther than this (m) are ignored
  int max_iterations = 500;        ///< Gauss-Newton steps, at most
  double convergence = 1e-4;       ///< stop when |update| (m + rad) is below this
  double degeneracy_ratio = 1e-3;  ///< eigenvalue / largest below which a direction is frozen
};

struct PointToPointIcpResult {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< sensor -> map
  int iterations = 0;
  bool converged = false;
  std::size_t correspondences = 0;  ///< at the final pose
  int degenerate_directions = 0;    ///< frozen directions at the last step (0-6)
  double eigen_ratio = 0.0;         ///< smallest / largest eigenvalue of the last normal matrix
};

/// \brief Align `source` (sensor frame) to `map`, starting from `initial`.
///
/// Each step pairs every source point with its nearest map point within the threshold, weights
/// the pair by the Geman-McClure kernel of scale threshold / 3, and solves the normal equations
/// of the right perturbation T exp(d) in the sensor frame (rotation scaled by the points' RMS
/// range so that both halves are in metres). Directions whose curvature is below
/// degeneracy_ratio of the largest are left out of the update, so along a corridor's axis the
/// pose stays where `initial` put it instead of sliding.
PointToPointIcpResult alignPointToPoint(const std::vector<Eigen::Vector3d>& source,
                                        const VoxelHashMap& map, const Eigen::Isometry3d& initial,
                                        const PointToPointIcpParams& params);

}  // namespace metricmap
