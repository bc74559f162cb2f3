#include "metricmap/posegraph/pose_graph.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>

#include "metricmap/common/format_number.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/posegraph/edge_error.h"

namespace metricmap {
namespace {

bool finitePose(const Pose2D& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta);
}

bool finitePose(const Pose3D& p) {
  return p.translation.allFinite() && p.rotation.coeffs().allFinite();
}

void checkTranslation(double v) {
  if (!(std::abs(v) <= kMaxTranslation)) {
    throw std::invalid_argument("a translation of " + formatNumber(v) + " m is beyond " +
                                formatNumber(kMaxTranslation) + " m");
  }
}

void checkPose(const Pose2D& p) {
  if (!finitePose(p)) throw std::invalid_argument("a pose value is not finite");
  checkTranslation(p.x);
  checkTranslation(p.y);
  if (!(std::abs(p.theta) <= kMaxAngle)) {
    throw std::invalid_argument("theta " + formatNumber(p.theta) + " rad is beyond " +
                                formatNumber(kMaxAngle) + " rad");
  }
}

void checkPose(const Pose3D& p) {
  if (!finitePose(p)) throw std::invalid_argument("a pose value is not finite");
  for (int i = 0; i < 3; ++i) checkTranslation(p.translation[i]);
  const double norm = p.rotation.norm();
  if (!(std::abs(norm - 1.0) <= kPoseQuaternionNormTolerance)) {
    throw std::invalid_argument("quaternion (qx qy qz qw) = (" + formatNumber(p.rotation.x()) +
                                " " + formatNumber(p.rotation.y()) + " " +
                                formatNumber(p.rotation.z()) + " " + formatNumber(p.rotation.w()) +
                                ") has norm " + formatNumber(norm) + ", not 1 (tolerance " +
                                formatNumber(kPoseQuaternionNormTolerance) + ")");
  }
}

Eigen::Vector3d errorOf(const Pose2D& xi, const Pose2D& xj, const Pose2D& z) {
  const double a[3] = {xi.x, xi.y, xi.theta};
  const double b[3] = {xj.x, xj.y, xj.theta};
  const double m[3] = {z.x, z.y, z.theta};
  Eigen::Vector3d e;
  detail::se2Error(a, b, m, e.data());
  return e;
}

Eigen::Matrix<double, 6, 1> errorOf(const Pose3D& xi, const Pose3D& xj, const Pose3D& z) {
  const Eigen::Quaterniond qi = xi.rotation.normalized();
  const Eigen::Quaterniond qj = xj.rotation.normalized();
  Eigen::Matrix<double, 6, 1> e;
  detail::se3Error(xi.translation.data(), qi.coeffs().data(), xj.translation.data(),
                   qj.coeffs().data(), z.translation, z.rotation.normalized(), e.data());
  return e;
}

}  // namespace

Pose2D compose(const Pose2D& a, const Pose2D& b) {
  const double c = std::cos(a.theta);
  const double s = std::sin(a.theta);
  return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, detail::wrapAngle(a.theta + b.theta)};
}

Pose2D inverse(const Pose2D& a) {
  const double c = std::cos(a.theta);
  const double s = std::sin(a.theta);
  return {-(c * a.x + s * a.y), s * a.x - c * a.y, detail::wrapAngle(-a.theta)};
}

Pose3D compose(const Pose3D& a, const Pose3D& b) {
  const Eigen::Quaterniond qa = a.rotation.normalized();
  Pose3D r;
  r.translation = a.translation + qa * b.translation;
  r.rotation = (qa * b.rotation.normalized()).normalized();
  return r;
}

Pose3D inverse(const Pose3D& a) {
  const Eigen::Quaterniond q = a.rotation.normalized().conjugate();
  Pose3D r;
  r.rotation = q;
  r.translation = -(q * a.translation);
  return r;
}

template <typename PoseT, int Dim>
void PoseGraph<PoseT, Dim>::validatePose(const Pose& pose) {
  checkPose(pose);
}

template <typename PoseT, int Dim>
void PoseGraph<PoseT, Dim>::validateInformation(const Information& information) {
  if (!information.allFinite()) {
    throw std::invalid_argument("the information matrix has an entry that is not finite");
  }
  if (information != information.transpose()) {
    throw std::invalid_argument("the information matrix is not symmetric");
  }
  const Eigen::LLT<Information> llt(information);
  if (llt.info() != Eigen::Success) {
    throw std::invalid_argument("the information matrix is not positive definite");
  }
}

template <typename PoseT, int Dim>
std::size_t PoseGraph<PoseT, Dim>::addVertex(std::int64_t id, const Pose& pose) {
  if (id < 0) throw std::invalid_argument("vertex id " + std::to_string(id) + " is negative");
  validatePose(pose);
  const auto [it, inserted] = index_.emplace(id, vertices_.size());
  if (!inserted) throw std::invalid_argument("vertex id " + std::to_string(id) + " exists already");
  try {
    vertices_.push_back(Vertex{id, pose, vertices_.empty()});
  } catch (...) {
    index_.erase(it);
    throw;
  }
  return vertices_.size() - 1;
}

template <typename PoseT, int Dim>
std::size_t PoseGraph<PoseT, Dim>::addEdge(std::size_t from, std::size_t to,
                                           const Pose& measurement, const Information& information,
                                           bool loop) {
  if (from >= vertices_.size() || to >= vertices_.size()) {
    throw std::invalid_argument("edge " + std::to_string(from) + " -> " + std::to_string(to) +
                                " names a vertex index beyond the " +
                                std::to_string(vertices_.size()) + " vertices");
  }
  if (from == to) {
    throw std::invalid_argument("an edge from vertex " + std::to_string(vertices_[from].id) +
                                " to itself");
  }
  validatePose(measurement);
  validateInformation(information);
  Edge edge;
  edge.from = from;
  edge.to = to;
  edge.measurement = measurement;
  edge.information = information;
  edge.loop = loop;
  edges_.push_back(edge);
  // The same rule as the g2o reader: an edge whose chi² overflows makes every cost infinite.
  if (!std::isfinite(edgeChi2(edges_.size() - 1))) {
    edges_.pop_back();
    throw std::invalid_argument(
        "the edge's chi² at the vertices' current poses is not finite (values too large)");
  }
  return edges_.size() - 1;
}

template <typename PoseT, int Dim>
std::optional<std::size_t> PoseGraph<PoseT, Dim>::find(std::int64_t id) const {
  const auto it = index_.find(id);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

template <typename PoseT, int Dim>
void PoseGraph<PoseT, Dim>::setFixed(std::size_t index, bool fixed) {
  vertices_.at(index).fixed = fixed;
}

template <typename PoseT, int Dim>
void PoseGraph<PoseT, Dim>::setPose(std::size_t index, const Pose& pose) {
  Vertex& v = vertices_.at(index);
  validatePose(pose);
  v.pose = pose;
}

template <typename PoseT, int Dim>
typename PoseGraph<PoseT, Dim>::Error PoseGraph<PoseT, Dim>::edgeError(std::size_t index) const {
  const Edge& e = edges_.at(index);
  return errorOf(vertices_[e.from].pose, vertices_[e.to].pose, e.measurement);
}

template <typename PoseT, int Dim>
double PoseGraph<PoseT, Dim>::edgeChi2(std::size_t index) const {
  const Error e = edgeError(index);
  return e.dot(edges_[index].information * e);
}

template <typename PoseT, int Dim>
double PoseGraph<PoseT, Dim>::chi2() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < edges_.size(); ++i) sum += edgeChi2(i);
  return sum;
}

template class PoseGraph<Pose2D, 3>;
template class PoseGraph<Pose3D, 6>;

}  // namespace metricmap
