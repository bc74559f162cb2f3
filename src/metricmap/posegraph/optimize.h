#pragma once
/// \file optimize.h
/// \brief Least-squares optimisation of a pose graph with Ceres (Levenberg-Marquardt, sparse
/// normal Cholesky), the formulation of Ceres' examples slam/pose_graph_2d and pose_graph_3d with
/// g2o's edge error: each edge's residual is S e with Sᵀ S = Ω (so that ‖S e‖² = eᵀ Ω e), the
/// heading kept in [-π, π) by an angle manifold, the quaternion on Ceres' EigenQuaternionManifold.
///
/// Ceres is linked privately: this header does not include it.

#include <cstdint>
#include <string>

#include "metricmap/posegraph/pose_graph.h"

namespace metricmap {

/// \brief A robust loss ρ(s) of an edge's chi² s = ‖S e‖², with scale a (Ceres' losses):
/// Huber ρ = s for s <= a², 2 a √s - a² beyond; Cauchy ρ = a² log(1 + s / a²).
enum class RobustLoss { None, Huber, Cauchy };

/// \brief "none" | "huber" | "cauchy". \throws std::invalid_argument naming the text
RobustLoss parseRobustLoss(const std::string& name);
/// \brief "none", "huber" or "cauchy".
const char* robustLossName(RobustLoss loss);

/// \brief How to optimise.
struct PoseGraphOptimizeOptions {
  int max_iterations = 100;  ///< Levenberg-Marquardt iterations, >= 1
  int threads = 1;           ///< Ceres' threads for residual and Jacobian evaluation, >= 1
  RobustLoss odometry_loss = RobustLoss::None;  ///< on edges whose `loop` is false
  RobustLoss loop_loss = RobustLoss::Huber;     ///< on edges whose `loop` is true
  /// The loss scale a in units of √chi² of one edge; 0: the square root of the 99 % quantile of
  /// chi² with the edge's degrees of freedom (√11.345 = 3.368 in 2D, √16.812 = 4.100 in 3D), the
  /// largest error a correct edge shows but once in a hundred.
  double loss_scale = 0.0;
  /// Levenberg-Marquardt's first trust-region radius; the damping starts at its inverse. A
  /// large radius starts as Gauss-Newton and damps only once a step fails: a small one (Ceres'
  /// default 1e4) damps the weak directions of a long chain or a badly conditioned graph so
  /// much that each step gains little and the function tolerance ends the run short of the
  /// optimum.
  double initial_trust_region_radius = 1e12;
  /// Ceres: stop when |Δcost| / cost of a step falls below it. A step's gain measures the
  /// damped step, not the distance to the optimum: 1e-10 stops within 1e-9 of the chi² of a
  /// plain Gauss-Newton on every shared graph, where 1e-6 stopped 2e-4 short (parking-garage).
  double function_tolerance = 1e-10;
  double gradient_tolerance = 1e-10;  ///< Ceres: stop when the max-norm of the gradient does
  double parameter_tolerance = 1e-8;  ///< Ceres: stop when the relative step does
};

/// \brief How the optimisation ended.
enum class PoseGraphTermination {
  Converged,      ///< one of the tolerances was met
  NoConvergence,  ///< max_iterations reached (the poses are the last iterate's)
  Failure         ///< the solver failed; the graph's poses are unchanged
};

/// \brief "converged", "no_convergence" or "failure".
const char* terminationName(PoseGraphTermination termination);

/// \brief What the optimisation did.
struct PoseGraphOptimizeResult {
  double initial_chi2 = 0.0;  ///< graph.chi2() before: Σ eᵀ Ω e (no robust loss)
  double final_chi2 = 0.0;    ///< graph.chi2() after
  /// Ceres' own cost before and after: ½ Σ ρ(eᵀ Ω e) (= chi² / 2 without a robust loss).
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;  ///< Levenberg-Marquardt steps tried (accepted and rejected)
  PoseGraphTermination termination = PoseGraphTermination::Failure;
  double seconds = 0.0;       ///< wall-clock time of the whole call (problem built and solved)
  std::string linear_solver;  ///< e.g. "SPARSE_NORMAL_CHOLESKY (SUITE_SPARSE)"
  std::string message;        ///< Ceres' reason for stopping
};

/// \brief The memory the solver of optimize() needs for `graph`, estimated from above: per
/// vertex its parameters (with gradient, step and trial copies), the diagonal block of the
/// normal equations and Ceres' bookkeeping (256 bytes a block); per edge its residuals, its
/// Jacobian's nonzeros (value and index, ambient and manifold columns: 2D 3 x 6, 3D 6 x 14 plus
/// 6 x 12) and two off-diagonal blocks of the normal equations with room for four times their
/// size of Cholesky fill-in.
std::uint64_t solverMemoryBytes(const PoseGraph2D& graph);
/// \copydoc solverMemoryBytes(const PoseGraph2D&)
std::uint64_t solverMemoryBytes(const PoseGraph3D& graph);
/// \brief The nonzeros of the edges' Jacobian (ambient columns): 18 an edge in 2D, 84 in 3D.
std::uint64_t jacobianNonzeros(const PoseGraph2D& graph);
/// \copydoc jacobianNonzeros(const PoseGraph2D&)
std::uint64_t jacobianNonzeros(const PoseGraph3D& graph);

/// \brief Optimise the poses of the non-fixed vertices in place (vertices without edges stay).
/// Angles of the result are wrapped to [-π, π), quaternions normalised. On Failure the poses are
/// left as they were.
/// \throws std::invalid_argument for options out of range, or a graph without edges (nothing
/// to optimise: never reported as converged)
/// \throws CapacityError when solverMemoryBytes() is beyond the memory budget (checked before
/// the problem is built)
PoseGraphOptimizeResult optimize(PoseGraph2D& graph, const PoseGraphOptimizeOptions& options = {});
/// \copydoc optimize(PoseGraph2D&, const PoseGraphOptimizeOptions&)
PoseGraphOptimizeResult optimize(PoseGraph3D& graph, const PoseGraphOptimizeOptions& options = {});

}  // namespace metricmap
