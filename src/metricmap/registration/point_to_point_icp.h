#pragma once
/// \file point_to_point_icp.h
/// \brief Robust point-to-point ICP of a scan against a VoxelHashMap: Gauss-Newton with a
/// Geman-McClure kernel; directions the scene does not constrain are held at the initial guess.

#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/registration/voxel_hash_map.h"

namespace metricmap {

class ThreadTeam;

struct PointToPointIcpParams {
  double threshold = 1.0;          ///< correspondences farther than this (m) are ignored
  int max_iterations = 500;        ///< Gauss-Newton steps, at most
  double convergence = 1e-4;       ///< stop when |update| (m + rad) is below this
  double degeneracy_ratio = 1e-3;  ///< eigenvalue / largest below which a direction is held
  /// \brief Threads for the pairing and the normal equations (0: all hardware threads). The
  /// sums are taken over fixed blocks of source points in a fixed order, so the result does
  /// not depend on this number.
  unsigned threads = 1;
};

struct PointToPointIcpResult {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< sensor -> map
  int iterations = 0;
  bool converged = false;
  std::size_t correspondences = 0;  ///< at the final pose
  int degenerate_directions = 0;    ///< directions held at the initial guess (0-6)
  double eigen_ratio = 0.0;         ///< smallest / largest eigenvalue of the surface information
};

/// \brief Buffers alignPointToPoint() may keep from call to call: a caller registering scan
/// after scan passes the same one, so that no call touches fresh memory.
/// A copy starts empty: two objects never share their threads.
struct PointToPointIcpWorkspace {
  PointToPointIcpWorkspace();
  ~PointToPointIcpWorkspace();
  PointToPointIcpWorkspace(const PointToPointIcpWorkspace&);
  PointToPointIcpWorkspace& operator=(const PointToPointIcpWorkspace&);
  PointToPointIcpWorkspace(PointToPointIcpWorkspace&&) noexcept;
  PointToPointIcpWorkspace& operator=(PointToPointIcpWorkspace&&) noexcept;

  std::vector<VoxelHashMap::Neighbourhood> neighbourhoods;  ///< one per source point
  std::unique_ptr<ThreadTeam> team;                         ///< the pairing's threads
};

/// \brief Align `source` (sensor frame) to `map`, starting from `initial`.
///
/// Each step pairs every source point with its nearest map point within the threshold, weights
/// the pair by the Geman-McClure kernel of scale threshold / 3, and solves the normal equations
/// of the right perturbation T exp(d) in the sensor frame.
///
/// Point-to-point normal equations are never singular (their translation block is a sum of
/// identities), so they cannot reveal a corridor: there the pairs simply slide along the axis.
/// The degeneracy test therefore uses the surfaces: at the final pose, the normal of each
/// matched map voxel holding at least 6 points that lie on a plane (smallest principal spread
/// below 2 % of the middle one) gives the point-to-plane
/// information matrix, rotation scaled by the points' RMS range so both halves are in metres.
/// Its eigen-directions below degeneracy_ratio of the largest are unobservable; the correction
/// from `initial` is projected off them, so the pose stays where `initial` put it along them.
PointToPointIcpResult alignPointToPoint(const std::vector<Eigen::Vector3d>& source,
                                        const VoxelHashMap& map, const Eigen::Isometry3d& initial,
                                        const PointToPointIcpParams& params,
                                        PointToPointIcpWorkspace* workspace = nullptr);

}  // namespace metricmap
