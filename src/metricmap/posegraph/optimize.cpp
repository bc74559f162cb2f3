#include "metricmap/posegraph/optimize.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <ceres/ceres.h>
#include <Eigen/Cholesky>

#include "metricmap/common/format_number.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/posegraph/edge_error.h"

namespace metricmap {
namespace {

/// √ of the 99 % quantile of chi² with 3 and 6 degrees of freedom.
constexpr double kDefaultLossScale2D = 3.3682;  // √11.3449
constexpr double kDefaultLossScale3D = 4.1002;  // √16.8119

/// Ceres' largest trust-region radius (its default max_trust_region_radius).
constexpr double kMaxTrustRegionRadius = 1e16;

/// S with Sᵀ S = Ω: the transposed lower Cholesky factor (Ω was checked positive definite).
template <int Dim>
Eigen::Matrix<double, Dim, Dim> sqrtInformation(const Eigen::Matrix<double, Dim, Dim>& omega) {
  return Eigen::LLT<Eigen::Matrix<double, Dim, Dim>>(omega).matrixL().transpose();
}

/// (x, y, θ) with θ wrapped to [-π, π) after every step; the tangent space is R³.
class Se2Manifold final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 3; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    x_plus_delta[0] = x[0] + delta[0];
    x_plus_delta[1] = x[1] + delta[1];
    x_plus_delta[2] = detail::wrapAngle(x[2] + delta[2]);
    return true;
  }
  bool PlusJacobian(const double* /*x*/, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(jacobian).setIdentity();
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    y_minus_x[0] = y[0] - x[0];
    y_minus_x[1] = y[1] - x[1];
    y_minus_x[2] = detail::wrapAngle(y[2] - x[2]);
    return true;
  }
  bool MinusJacobian(const double* /*x*/, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(jacobian).setIdentity();
    return true;
  }
};

/// S e of an SE(2) edge; parameters: x_i, x_j as (x, y, θ).
struct Se2Residual {
  double z[3];
  Eigen::Matrix3d sqrt_information;

  template <typename T>
  bool operator()(const T* xi, const T* xj, T* residual) const {
    T e[3];
    detail::se2Error(xi, xj, z, e);
    for (int r = 0; r < 3; ++r) {
      residual[r] = sqrt_information(r, 0) * e[0] + sqrt_information(r, 1) * e[1] +
                    sqrt_information(r, 2) * e[2];
    }
    return true;
  }
};

/// S e of an SE(3) edge; parameters: t_i, q_i, t_j, q_j (quaternions in Eigen's x y z w order).
struct Se3Residual {
  Eigen::Vector3d tz;
  Eigen::Quaterniond qz;
  Eigen::Matrix<double, 6, 6> sqrt_information;

  template <typename T>
  bool operator()(const T* ti, const T* qi, const T* tj, const T* qj, T* residual) const {
    T e[6];
    detail::se3Error(ti, qi, tj, qj, tz, qz, e);
    for (int r = 0; r < 6; ++r) {
      T sum(0.0);
      for (int c = 0; c < 6; ++c) sum += sqrt_information(r, c) * e[c];
      residual[r] = sum;
    }
    return true;
  }
};

void checkOptions(const PoseGraphOptimizeOptions& o) {
  if (o.max_iterations < 1) {
    throw std::invalid_argument("max_iterations must be at least 1, got " +
                                std::to_string(o.max_iterations));
  }
  if (o.threads < 1) {
    throw std::invalid_argument("threads must be at least 1, got " + std::to_string(o.threads));
  }
  const auto nonNegative = [](double v, const char* name) {
    if (!(std::isfinite(v) && v >= 0.0)) {
      throw std::invalid_argument(std::string(name) + " must be a finite number >= 0, got " +
                                  formatNumber(v));
    }
  };
  nonNegative(o.loss_scale, "loss_scale");
  nonNegative(o.function_tolerance, "function_tolerance");
  nonNegative(o.gradient_tolerance, "gradient_tolerance");
  nonNegative(o.parameter_tolerance, "parameter_tolerance");
  if (!(std::isfinite(o.initial_trust_region_radius) && o.initial_trust_region_radius > 0.0 &&
        o.initial_trust_region_radius <= kMaxTrustRegionRadius)) {
    throw std::invalid_argument("initial_trust_region_radius must be in (0, 1e16], got " +
                                formatNumber(o.initial_trust_region_radius));
  }
}

std::unique_ptr<ceres::LossFunction> makeLoss(RobustLoss loss, double scale) {
  switch (loss) {
    case RobustLoss::Huber:
      return std::make_unique<ceres::HuberLoss>(scale);
    case RobustLoss::Cauchy:
      return std::make_unique<ceres::CauchyLoss>(scale);
    default:
      return nullptr;
  }
}

/// What the graph's optimisation shares between 2D and 3D: the losses, the solver's options,
/// the run and the result.
class Run {
 public:
  Run(const PoseGraphOptimizeOptions& options, double default_scale)
      : options_(options), start_(std::chrono::steady_clock::now()) {
    checkOptions(options);
    const double scale = options.loss_scale > 0.0 ? options.loss_scale : default_scale;
    odometry_loss_ = makeLoss(options.odometry_loss, scale);
    loop_loss_ = makeLoss(options.loop_loss, scale);
    ceres::Problem::Options po;
    po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    po.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    problem_ = std::make_unique<ceres::Problem>(po);
  }

  ceres::Problem& problem() { return *problem_; }
  ceres::LossFunction* loss(bool loop) const {
    return loop ? loop_loss_.get() : odometry_loss_.get();
  }

  /// Solve; true when the parameter blocks hold a usable solution.
  bool solve(PoseGraphOptimizeResult& result) {
    ceres::Solver::Options so;
    so.minimizer_type = ceres::TRUST_REGION;
    so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    so.max_num_iterations = options_.max_iterations;
    so.initial_trust_region_radius = options_.initial_trust_region_radius;
    so.max_trust_region_radius = kMaxTrustRegionRadius;
    so.num_threads = options_.threads;
    so.function_tolerance = options_.function_tolerance;
    so.gradient_tolerance = options_.gradient_tolerance;
    so.parameter_tolerance = options_.parameter_tolerance;
    so.logging_type = ceres::SILENT;
    so.minimizer_progress_to_stdout = false;
    so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    const ceres::SparseLinearAlgebraLibraryType libraries[] = {
        ceres::SUITE_SPARSE, ceres::EIGEN_SPARSE, ceres::CX_SPARSE, ceres::ACCELERATE_SPARSE};
    bool sparse = false;
    for (const auto library : libraries) {
      if (ceres::IsSparseLinearAlgebraLibraryTypeAvailable(library)) {
        so.sparse_linear_algebra_library_type = library;
        sparse = true;
        break;
      }
    }
    if (!sparse) so.linear_solver_type = ceres::DENSE_QR;  // a Ceres without sparse support
    result.linear_solver = ceres::LinearSolverTypeToString(so.linear_solver_type);
    if (sparse) {
      result.linear_solver +=
          std::string(" (") +
          ceres::SparseLinearAlgebraLibraryTypeToString(so.sparse_linear_algebra_library_type) +
          ")";
    }
    std::string why;
    if (!so.IsValid(&why)) throw std::invalid_argument("Ceres solver options: " + why);
    ceres::Solver::Summary summary;
    ceres::Solve(so, problem_.get(), &summary);
    result.initial_cost = summary.initial_cost;
    result.final_cost = summary.final_cost;
    result.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
    result.message = summary.message;
    switch (summary.termination_type) {
      case ceres::CONVERGENCE:
      case ceres::USER_SUCCESS:
        result.termination = PoseGraphTermination::Converged;
        break;
      case ceres::NO_CONVERGENCE:
        result.termination = PoseGraphTermination::NoConvergence;
        break;
      default:
        result.termination = PoseGraphTermination::Failure;
    }
    if (!summary.IsSolutionUsable()) result.termination = PoseGraphTermination::Failure;
    return result.termination != PoseGraphTermination::Failure;
  }

  void finish(PoseGraphOptimizeResult& result) const {
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  PoseGraphOptimizeOptions options_;
  std::chrono::steady_clock::time_point start_;
  std::unique_ptr<ceres::LossFunction> odometry_loss_;
  std::unique_ptr<ceres::LossFunction> loop_loss_;
  std::unique_ptr<ceres::Problem> problem_;
};

}  // namespace

RobustLoss parseRobustLoss(const std::string& name) {
  if (name == "none") return RobustLoss::None;
  if (name == "huber") return RobustLoss::Huber;
  if (name == "cauchy") return RobustLoss::Cauchy;
  throw std::invalid_argument("robust loss must be none, huber or cauchy, got '" +
                              quoteForMessage(name) + "'");
}

const char* robustLossName(RobustLoss loss) {
  switch (loss) {
    case RobustLoss::Huber:
      return "huber";
    case RobustLoss::Cauchy:
      return "cauchy";
    default:
      return "none";
  }
}

const char* terminationName(PoseGraphTermination termination) {
  switch (termination) {
    case PoseGraphTermination::Converged:
      return "converged";
    case PoseGraphTermination::NoConvergence:
      return "no_convergence";
    default:
      return "failure";
  }
}

namespace {

/// Bytes per vertex and per edge of a graph whose poses have `params` numbers (`tangent` on the
/// manifold) and whose edges have `residuals` numbers, as solverMemoryBytes documents.
std::uint64_t solverBytes(std::uint64_t vertices, std::uint64_t edges, std::uint64_t params,
                          std::uint64_t tangent, std::uint64_t residuals, std::uint64_t blocks) {
  constexpr std::uint64_t kBlock = 256, kNonzero = 8 + 4, kFill = 4;
  const std::uint64_t per_vertex = 4 * 8 * params + tangent * tangent * kNonzero + blocks * kBlock;
  const std::uint64_t per_edge = residuals * 8 * 4 + residuals * 2 * (params + tangent) * kNonzero +
                                 2 * tangent * tangent * kNonzero * kFill + kBlock;
  return vertices * per_vertex + edges * per_edge;
}

/// CapacityError before a problem beyond the budget is built.
template <typename Graph>
void checkSolverBudget(const Graph& graph) {
  checkMemory(1, solverMemoryBytes(graph),
              "the pose graph's solver (" + std::to_string(graph.vertexCount()) + " vertices, " +
                  std::to_string(graph.edgeCount()) + " edges, " +
                  std::to_string(jacobianNonzeros(graph)) + " Jacobian nonzeros)");
}

}  // namespace

namespace {

/// A graph without edges has nothing to optimise: refused, never reported as converged.
void requireEdges(std::size_t vertices, std::size_t edges) {
  if (edges == 0) {
    throw std::invalid_argument("the graph has " + std::to_string(vertices) +
                                " vertices and no edge: nothing to optimise");
  }
}

}  // namespace

std::uint64_t solverMemoryBytes(const PoseGraph2D& graph) {
  return solverBytes(graph.vertexCount(), graph.edgeCount(), 3, 3, 3, 1);
}

std::uint64_t solverMemoryBytes(const PoseGraph3D& graph) {
  return solverBytes(graph.vertexCount(), graph.edgeCount(), 7, 6, 6, 2);
}

std::uint64_t jacobianNonzeros(const PoseGraph2D& graph) {
  return static_cast<std::uint64_t>(graph.edgeCount()) * 3 * 6;
}

std::uint64_t jacobianNonzeros(const PoseGraph3D& graph) {
  return static_cast<std::uint64_t>(graph.edgeCount()) * 6 * 14;
}

PoseGraphOptimizeResult optimize(PoseGraph2D& graph, const PoseGraphOptimizeOptions& options) {
  checkSolverBudget(graph);
  Se2Manifold manifold;  // outlives the problem, which does not own it
  Run run(options, kDefaultLossScale2D);
  requireEdges(graph.vertexCount(), graph.edgeCount());  // after the options' checks
  PoseGraphOptimizeResult result;
  result.initial_chi2 = result.final_chi2 = graph.chi2();
  const std::size_t n = graph.vertexCount();
  std::vector<double> x(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Pose2D& p = graph.vertex(i).pose;
    x[3 * i] = p.x;
    x[3 * i + 1] = p.y;
    x[3 * i + 2] = detail::wrapAngle(p.theta);
  }
  ceres::Problem& problem = run.problem();
  for (const PoseGraph2D::Edge& e : graph.edges()) {
    auto* functor = new Se2Residual{{e.measurement.x, e.measurement.y, e.measurement.theta},
                                    sqrtInformation<3>(e.information)};
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Se2Residual, 3, 3, 3>(functor),
                             run.loss(e.loop), &x[3 * e.from], &x[3 * e.to]);
  }
  std::vector<bool> in_problem(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    double* block = &x[3 * i];
    if (!problem.HasParameterBlock(block)) continue;
    in_problem[i] = true;
    problem.SetManifold(block, &manifold);
    if (graph.vertex(i).fixed) problem.SetParameterBlockConstant(block);
  }
  if (run.solve(result)) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!in_problem[i] || graph.vertex(i).fixed) continue;
      graph.setPose(i, Pose2D{x[3 * i], x[3 * i + 1], detail::wrapAngle(x[3 * i + 2])});
    }
    result.final_chi2 = graph.chi2();
  }
  run.finish(result);
  return result;
}

PoseGraphOptimizeResult optimize(PoseGraph3D& graph, const PoseGraphOptimizeOptions& options) {
  checkSolverBudget(graph);
  ceres::EigenQuaternionManifold manifold;  // outlives the problem, which does not own it
  Run run(options, kDefaultLossScale3D);
  requireEdges(graph.vertexCount(), graph.edgeCount());  // after the options' checks
  PoseGraphOptimizeResult result;
  result.initial_chi2 = result.final_chi2 = graph.chi2();
  const std::size_t n = graph.vertexCount();
  std::vector<double> t(3 * n);
  std::vector<double> q(4 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Pose3D& p = graph.vertex(i).pose;
    Eigen::Map<Eigen::Vector3d> ti(&t[3 * i]);
    Eigen::Map<Eigen::Vector4d> qi(&q[4 * i]);
    ti = p.translation;
    qi = p.rotation.normalized().coeffs();
  }
  ceres::Problem& problem = run.problem();
  for (const PoseGraph3D::Edge& e : graph.edges()) {
    auto* functor = new Se3Residual{e.measurement.translation, e.measurement.rotation.normalized(),
                                    sqrtInformation<6>(e.information)};
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Se3Residual, 6, 3, 4, 3, 4>(functor),
                             run.loss(e.loop), &t[3 * e.from], &q[4 * e.from], &t[3 * e.to],
                             &q[4 * e.to]);
  }
  std::vector<bool> in_problem(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    if (!problem.HasParameterBlock(&t[3 * i])) continue;
    in_problem[i] = true;
    problem.SetManifold(&q[4 * i], &manifold);
    if (graph.vertex(i).fixed) {
      problem.SetParameterBlockConstant(&t[3 * i]);
      problem.SetParameterBlockConstant(&q[4 * i]);
    }
  }
  if (run.solve(result)) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!in_problem[i] || graph.vertex(i).fixed) continue;
      Pose3D p;
      p.translation = Eigen::Map<const Eigen::Vector3d>(&t[3 * i]);
      p.rotation.coeffs() = Eigen::Map<const Eigen::Vector4d>(&q[4 * i]);
      p.rotation.normalize();
      graph.setPose(i, p);
    }
    result.final_chi2 = graph.chi2();
  }
  run.finish(result);
  return result;
}

}  // namespace metricmap
