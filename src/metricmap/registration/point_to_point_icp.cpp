#include "metricmap/registration/point_to_point_icp.h"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "metricmap/registration/se3.h"

namespace metricmap {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct NormalEquations {
  Matrix6d h = Matrix6d::Zero();
  Vector6d g = Vector6d::Zero();
  std::size_t pairs = 0;
};

// Pairs and normal equations at pose t. Residual in the sensor frame r = R^T (t p - q);
// its Jacobian for the scaled right perturbation (dt, L dtheta) is [I, -[p]x / L].
NormalEquations buildSystem(const std::vector<Eigen::Vector3d>& source, const VoxelHashMap& map,
                            const Eigen::Isometry3d& t, double threshold, double inv_scale) {
  NormalEquations ne;
  const Eigen::Matrix3d rt = t.linear().transpose();
  const double kernel2 = (threshold / 3.0) * (threshold / 3.0);
  Eigen::Vector3d q;
  for (const Eigen::Vector3d& p : source) {
    const Eigen::Vector3d w = t * p;
    if (!map.nearest(w, threshold, q)) continue;
    const Eigen::Vector3d r = rt * (w - q);
    const double e2 = r.squaredNorm() / kernel2;
    const double weight = 1.0 / ((1.0 + e2) * (1.0 + e2));
    const Eigen::Vector3d ps = p * inv_scale;
    Eigen::Matrix<double, 3, 6> j;
    j.leftCols<3>().setIdentity();
    j.rightCols<3>() << 0, ps.z(), -ps.y(), -ps.z(), 0, ps.x(), ps.y(), -ps.x(), 0;
    ne.h.noalias() += weight * j.transpose() * j;
    ne.g.noalias() += weight * j.transpose() * r;
    ++ne.pairs;
  }
  return ne;
}

}  // namespace

PointToPointIcpResult alignPointToPoint(const std::vector<Eigen::Vector3d>& source,
                                        const VoxelHashMap& map, const Eigen::Isometry3d& initial,
                                        const PointToPointIcpParams& params) {
  PointToPointIcpResult res;
  res.pose = initial;
  if (source.empty() || map.empty()) return res;
  double sq = 0.0;
  for (const auto& p : source) sq += p.squaredNorm();
  const double scale = std::max(1.0, std::sqrt(sq / static_cast<double>(source.size())));
  const double inv_scale = 1.0 / scale;
  for (res.iterations = 0; res.iterations < params.max_iterations;) {
    const NormalEquations ne = buildSystem(source, map, res.pose, params.threshold, inv_scale);
    res.correspondences = ne.pairs;
    if (ne.pairs < 6) break;
    const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(ne.h);
    const Vector6d lambda = eig.eigenvalues();  // ascending
    const double largest = lambda(5);
    if (!(largest > 0.0)) break;
    res.eigen_ratio = lambda(0) / largest;
    res.degenerate_directions = 0;
    Vector6d step = Vector6d::Zero();
    for (int i = 0; i < 6; ++i) {
      if (lambda(i) < params.degeneracy_ratio * largest) {
        ++res.degenerate_directions;
        continue;
      }
      const Vector6d v = eig.eigenvectors().col(i);
      step -= v * (v.dot(ne.g) / lambda(i));
    }
    step.tail<3>() *= inv_scale;
    res.pose = res.pose * se3Exp(step);
    ++res.iterations;
    if (step.norm() < params.convergence) {
      res.converged = true;
      break;
    }
  }
  // Pairs at the final pose (the loop counted them before its last step).
  Eigen::Vector3d q;
  res.correspondences = 0;
  for (const Eigen::Vector3d& p : source) {
    res.correspondences += map.nearest(res.pose * p, params.threshold, q) ? 1 : 0;
  }
  return res;
}

}  // namespace metricmap
