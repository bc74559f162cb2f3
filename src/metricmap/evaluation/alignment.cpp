#include "metricmap/evaluation/alignment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>

namespace metricmap {

AlignmentMode parseAlignmentMode(const std::string& name) {
  if (name == "none") return AlignmentMode::None;
  if (name == "rigid") return AlignmentMode::Rigid;
  if (name == "sim") return AlignmentMode::Similarity;
  throw std::invalid_argument("alignment must be none, rigid or sim, got '" + name + "'");
}

const char* alignmentModeName(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::Rigid:
      return "rigid";
    case AlignmentMode::Similarity:
      return "sim";
    default:
      return "none";
  }
}

Eigen::Isometry3d Alignment::apply(const Eigen::Isometry3d& pose) const {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = rotation * pose.linear();
  out.translation() = scale * (rotation * pose.translation()) + translation;
  return out;
}

Alignment alignPositions(const std::vector<Eigen::Isometry3d>& estimate,
                         const std::vector<Eigen::Isometry3d>& reference, AlignmentMode mode) {
  if (estimate.size() != reference.size() || estimate.empty()) {
    throw std::invalid_argument("alignment: " + std::to_string(estimate.size()) +
                                " estimated and " + std::to_string(reference.size()) +
                                " reference positions (the same number > 0 needed)");
  }
  if (mode == AlignmentMode::None) return Alignment{};
  const Eigen::Index n = static_cast<Eigen::Index>(estimate.size());
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    src.col(i) = estimate[static_cast<std::size_t>(i)].translation();
    dst.col(i) = reference[static_cast<std::size_t>(i)].translation();
  }
  // evo's check: the cross-covariance must have rank >= 2 (numpy's matrix_rank tolerance).
  const Eigen::Matrix3Xd src_c = src.colwise() - src.rowwise().mean();
  const Eigen::Matrix3Xd dst_c = dst.colwise() - dst.rowwise().mean();
  const Eigen::Matrix3d cov = dst_c * src_c.transpose() / static_cast<double>(n);
  const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix3d>(cov).singularValues();
  if (!(sv(1) > sv(0) * 3.0 * std::numeric_limits<double>::epsilon())) {
    throw std::invalid_argument(
        "alignment: the positions are collinear or coincide (cross-covariance rank below 2), "
        "so no rotation aligns them; use --align none");
  }
  // Rank 2 in floating point is not enough: the rotation about the positions' main direction is
  // fixed only by what the two trajectories share across it. Near-collinear positions (a spread
  // across below 1e-4 of the spread along, i.e. second singular value below 1e-8 of the first),
  // or a spread across that the two do not share (noise: the second singular value of the
  // cross-covariance below a quarter of what the positions' own second variances would give if
  // they agreed) leave that rotation to chance: refused, never a rotation by noise.
  const Eigen::Vector3d vs = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(
                                 src_c * src_c.transpose() / static_cast<double>(n))
                                 .eigenvalues();  // increasing
  const Eigen::Vector3d vd = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(
                                 dst_c * dst_c.transpose() / static_cast<double>(n))
                                 .eigenvalues();
  const double shared = std::sqrt(std::max(0.0, vs(1)) * std::max(0.0, vd(1)));
  if (!(sv(1) > sv(0) * 1e-8) || !(sv(1) >= 0.25 * shared)) {
    char ratio[64];
    std::snprintf(ratio, sizeof ratio, "%.3g", sv(1) / sv(0));
    throw std::invalid_argument(
        std::string("alignment: the positions are nearly collinear (cross-covariance singular "
                    "values ") +
        ratio + " of the largest across the path" +
        (sv(1) > sv(0) * 1e-8 ? ", and what lies across it differs between the trajectories" : "") +
        "), so the rotation about the path is not determined; use --align none");
  }
  const Eigen::Matrix4d t = Eigen::umeyama(src, dst, mode == AlignmentMode::Similarity);
  Alignment a;
  a.scale = mode == AlignmentMode::Similarity ? t.block<3, 1>(0, 0).norm() : 1.0;
  a.rotation = t.topLeftCorner<3, 3>() / a.scale;
  a.translation = t.topRightCorner<3, 1>();
  if (!a.rotation.allFinite() || !a.translation.allFinite() || !std::isfinite(a.scale) ||
      !(a.scale > 0.0)) {
    throw std::invalid_argument("alignment: no finite solution for these positions");
  }
  return a;
}

std::vector<Eigen::Isometry3d> applyAlignment(const Alignment& alignment,
                                              const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Isometry3d> out;
  out.reserve(poses.size());
  for (const Eigen::Isometry3d& p : poses) out.push_back(alignment.apply(p));
  return out;
}

}  // namespace metricmap
