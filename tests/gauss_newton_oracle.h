#pragma once
// An independent pose-graph solver for tests: plain Gauss-Newton (no damping, no robust loss)
// on g2o's edge error computed through Eigen's Isometry types, Jacobians by central
// differences, normal equations solved with Eigen's sparse LDLᵀ. It shares no code with the
// library's optimiser but the graph types it reads.
//
// SE(2) unknowns are (x, y, θ) added directly; SE(3) unknowns are (δt, δω) with
// x ⊞ δ = (t + δt, q exp(δω)). Fixed vertices are not unknowns.

#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include "metricmap/posegraph/pose_graph.h"

namespace metricmap::test_support {

struct GaussNewtonResult {
  double chi2 = 0.0;
  int iterations = 0;
  bool converged = false;  ///< chi² changed by less than `tolerance` (relative) in a step
};

namespace gn_detail {

inline Eigen::Isometry2d iso(const Pose2D& p) {
  Eigen::Isometry2d t = Eigen::Isometry2d::Identity();
  t.translate(Eigen::Vector2d(p.x, p.y));
  t.rotate(Eigen::Rotation2Dd(p.theta));
  return t;
}

inline Eigen::Isometry3d iso(const Pose3D& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(p.translation);
  t.rotate(p.rotation.normalized());
  return t;
}

/// z⁻¹ (x_i⁻¹ x_j) as (x, y, angle).
inline Eigen::Vector3d error(const Pose2D& xi, const Pose2D& xj, const Pose2D& z) {
  const Eigen::Isometry2d d = iso(z).inverse() * (iso(xi).inverse() * iso(xj));
  return {d.translation().x(), d.translation().y(), std::atan2(d.linear()(1, 0), d.linear()(0, 0))};
}

/// z⁻¹ (x_i⁻¹ x_j) as (translation, vector part of the quaternion with w >= 0).
inline Eigen::Matrix<double, 6, 1> error(const Pose3D& xi, const Pose3D& xj, const Pose3D& z) {
  const Eigen::Isometry3d d = iso(z).inverse() * (iso(xi).inverse() * iso(xj));
  Eigen::Quaterniond q(d.rotation());
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  Eigen::Matrix<double, 6, 1> e;
  e << d.translation(), q.vec();
  return e;
}

inline Pose2D plus(const Pose2D& x, const double* d) {
  return Pose2D{x.x + d[0], x.y + d[1], x.theta + d[2]};
}

inline Pose3D plus(const Pose3D& x, const double* d) {
  Pose3D r;
  r.translation = x.translation + Eigen::Vector3d(d[0], d[1], d[2]);
  const Eigen::Vector3d w(d[3], d[4], d[5]);
  const double angle = w.norm();
  const Eigen::Quaterniond dq = angle > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, w / angle))
                                          : Eigen::Quaterniond::Identity();
  r.rotation = (x.rotation.normalized() * dq).normalized();
  return r;
}

}  // namespace gn_detail

/// Σ eᵀ Ω e at the graph's poses, through the oracle's error.
template <typename Graph>
double oracleChi2(const Graph& g) {
  double sum = 0.0;
  for (const auto& e : g.edges()) {
    const auto r = gn_detail::error(g.vertex(e.from).pose, g.vertex(e.to).pose, e.measurement);
    sum += r.dot(e.information * r);
  }
  return sum;
}

/// Plain Gauss-Newton on `g` in place until a step changes chi² by less than `tolerance` times
/// chi², or `max_iterations` steps were taken.
template <typename Graph>
GaussNewtonResult gaussNewton(Graph& g, int max_iterations = 100, double tolerance = 1e-10) {
  constexpr int D = Graph::kDim;
  using Pose = typename Graph::Pose;
  using Block = Eigen::Matrix<double, D, D>;
  using Vec = Eigen::Matrix<double, D, 1>;
  const std::size_t n = g.vertexCount();
  std::vector<long> column(n, -1);  // first unknown of each free vertex
  long m = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!g.vertex(i).fixed) {
      column[i] = m;
      m += D;
    }
  }
  GaussNewtonResult result;
  constexpr double h = 1e-6;
  double chi2 = oracleChi2(g);
  for (result.iterations = 1; result.iterations <= max_iterations; ++result.iterations) {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(g.edgeCount() * 4 * D * D + static_cast<std::size_t>(m));
    Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
    for (long k = 0; k < m; ++k) triplets.emplace_back(k, k, 1e-12);  // vertices without edges
    for (const auto& e : g.edges()) {
      const Pose pose[2] = {g.vertex(e.from).pose, g.vertex(e.to).pose};
      const Vec r = gn_detail::error(pose[0], pose[1], e.measurement);
      Eigen::Matrix<double, D, 2 * D> J;
      for (int k = 0; k < 2 * D; ++k) {
        double d[D] = {};
        d[k % D] = h;
        Pose moved[2] = {pose[0], pose[1]};
        moved[k / D] = gn_detail::plus(pose[k / D], d);
        const Vec up = gn_detail::error(moved[0], moved[1], e.measurement);
        d[k % D] = -h;
        moved[k / D] = gn_detail::plus(pose[k / D], d);
        const Vec down = gn_detail::error(moved[0], moved[1], e.measurement);
        J.col(k) = (up - down) / (2 * h);
      }
      const std::size_t vertex[2] = {e.from, e.to};
      for (int a = 0; a < 2; ++a) {
        if (column[vertex[a]] < 0) continue;
        const Eigen::Matrix<double, D, D> Ja = J.template middleCols<D>(D * a);
        b.template segment<D>(column[vertex[a]]) += Ja.transpose() * e.information * r;
        for (int c = 0; c < 2; ++c) {
          if (column[vertex[c]] < 0) continue;
          const Block H = Ja.transpose() * e.information * J.template middleCols<D>(D * c);
          for (int p = 0; p < D; ++p) {
            for (int q = 0; q < D; ++q) {
              triplets.emplace_back(column[vertex[a]] + p, column[vertex[c]] + q, H(p, q));
            }
          }
        }
      }
    }
    Eigen::SparseMatrix<double> H(m, m);
    H.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(H);
    if (solver.info() != Eigen::Success) break;
    const Eigen::VectorXd dx = solver.solve(-b);
    for (std::size_t i = 0; i < n; ++i) {
      if (column[i] < 0) continue;
      g.setPose(i, gn_detail::plus(g.vertex(i).pose, dx.data() + column[i]));
    }
    const double next = oracleChi2(g);
    const bool flat = std::abs(chi2 - next) <= tolerance * next;
    chi2 = next;
    if (flat) {
      result.converged = true;
      break;
    }
  }
  result.chi2 = oracleChi2(g);
  return result;
}

}  // namespace metricmap::test_support
