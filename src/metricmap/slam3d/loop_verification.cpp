#include "metricmap/slam3d/loop_verification.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "metricmap/registration/point_to_point_icp.h"
#include "metricmap/registration/voxel_hash_map.h"

namespace metricmap {
namespace {

void positive(double v, const char* name) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(name) + " must be finite and > 0");
}
void share(double v, const char* name) {
  if (!(v >= 0.0 && v <= 1.0))
    throw std::invalid_argument(std::string(name) + " must be in [0, 1]");
}

// The height below which a point is ground: the 10th percentile of z plus the margin.
double groundLevel(std::vector<double> z, double margin) {
  if (z.empty()) return 0.0;
  const std::size_t k = z.size() / 10;
  std::nth_element(z.begin(), z.begin() + static_cast<std::ptrdiff_t>(k), z.end());
  return z[k] + margin;
}

}  // namespace

void validateLoopVerificationParams(const LoopVerificationParams& p) {
  positive(p.coarse_threshold, "verify coarse_threshold");
  positive(p.fine_threshold, "verify fine_threshold");
  if (p.fine_threshold > p.coarse_threshold)
    throw std::invalid_argument("verify fine_threshold must be <= coarse_threshold");
  positive(p.map_voxel, "verify map_voxel");
  positive(p.overlap_distance, "verify overlap_distance");
  share(p.min_overlap, "verify min_overlap");
  share(p.min_structure_overlap, "verify min_structure_overlap");
  if (!(p.ground_margin >= 0.0) || !std::isfinite(p.ground_margin))
    throw std::invalid_argument("verify ground_margin must be finite and >= 0");
  positive(p.max_correction, "verify max_correction");
}

LoopVerification verifyLoop(const std::vector<Eigen::Vector3f>& query,
                            const std::vector<Eigen::Vector3f>& candidate,
                            const Eigen::Isometry3d& initial, const LoopVerificationParams& p) {
  validateLoopVerificationParams(p);
  LoopVerification v;
  v.relation = initial;
  std::vector<Eigen::Vector3d> source, target;
  source.reserve(query.size());
  target.reserve(candidate.size());
  for (const auto& q : query)
    if (q.allFinite()) source.push_back(q.cast<double>());
  for (const auto& q : candidate)
    if (q.allFinite()) target.push_back(q.cast<double>());
  if (source.size() < 50 || target.size() < 50) {
    v.reason = "too few points";
    return v;
  }
  VoxelHashMap map(p.map_voxel, 20);
  map.add(target);
  PointToPointIcpParams icp;
  icp.max_iterations = 50;
  icp.convergence = 1e-4;
  // The map's voxels hold a few averaged points each: too few for the surface test of the
  // odometry's degeneracy check. The overlap tests below judge the alignment instead.
  icp.degeneracy_ratio = 0.0;
  PointToPointIcpWorkspace workspace;
  Eigen::Isometry3d pose = initial;
  PointToPointIcpResult r;
  for (double threshold = p.coarse_threshold;;
       threshold = std::max(p.fine_threshold, threshold / 2)) {
    icp.threshold = threshold;
    r = alignPointToPoint(source, map, pose, icp, &workspace);
    pose = r.pose;
    if (threshold <= p.fine_threshold) break;
  }
  v.relation = pose;
  v.degenerate_directions = r.degenerate_directions;

  std::vector<double> z(source.size());
  for (std::size_t i = 0; i < source.size(); ++i) z[i] = source[i].z();
  const double ground = groundLevel(z, p.ground_margin);
  std::size_t hits = 0, structure = 0, structure_hits = 0;
  double sq = 0.0;
  Eigen::Vector3d nearest;
  for (const Eigen::Vector3d& s : source) {
    const bool high = s.z() > ground;
    structure += high ? 1 : 0;
    if (map.nearest(pose * s, p.overlap_distance, nearest)) {
      ++hits;
      structure_hits += high ? 1 : 0;
      sq += (pose * s - nearest).squaredNorm();
    }
  }
  v.overlap = double(hits) / double(source.size());
  v.structure_overlap = structure > 0 ? double(structure_hits) / double(structure) : 0.0;
  v.rmse = hits > 0 ? std::sqrt(sq / double(hits)) : 0.0;
  const double correction = (initial.inverse() * pose).translation().norm();
  if (correction > p.max_correction)
    v.reason = "correction too large";
  else if (v.overlap < p.min_overlap)
    v.reason = "overlap too small";
  else if (v.structure_overlap < p.min_structure_overlap)
    v.reason = "structure overlap too small";
  else
    v.accepted = true;
  return v;
}

}  // namespace metricmap
