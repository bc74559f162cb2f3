#include "metricmap/localization/scan_ground_3d.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace metricmap {
namespace {

constexpr std::size_t kMinInliers = 30;
constexpr int kIterations = 200;

double percentileZ(const std::vector<Eigen::Vector3d>& points, double share) {
  std::vector<double> z;
  z.reserve(points.size());
  for (const Eigen::Vector3d& p : points) z.push_back(p.z());
  if (z.empty()) return 0.0;
  const auto k = static_cast<std::ptrdiff_t>(share * static_cast<double>(z.size() - 1));
  std::nth_element(z.begin(), z.begin() + k, z.end());
  return z[static_cast<std::size_t>(k)];
}

/// Plane n.p + d = 0 through `pts` by least squares (smallest principal direction), n.z > 0.
bool fitPlane(const std::vector<Eigen::Vector3d>& pts, Eigen::Vector3d& n, double& d) {
  if (pts.size() < 3) return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  n = es.eigenvectors().col(0);
  if (n.z() < 0) n = -n;
  d = -n.dot(mean);
  return true;
}

}  // namespace

ScanGround estimateScanGround(const std::vector<Eigen::Vector3d>& points, double threshold,
                              double max_tilt_deg) {
  ScanGround g;
  std::vector<Eigen::Vector3d> near;
  for (const Eigen::Vector3d& p : points) {
    const double r = std::hypot(p.x(), p.y());
    if (r >= 2.0 && r <= 30.0 && p.allFinite()) near.push_back(p);
  }
  g.height = -percentileZ(points, 0.1);
  if (near.size() < kMinInliers) return g;
  const double low = percentileZ(near, 0.3);
  std::vector<Eigen::Vector3d> cand;
  for (const Eigen::Vector3d& p : near)
    if (p.z() <= low) cand.push_back(p);
  if (cand.size() < kMinInliers) return g;
  const double min_cos = std::cos(max_tilt_deg * M_PI / 180.0);
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state](std::size_t n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::size_t>((state >> 33) % n);
  };
  std::size_t best = 0;
  Eigen::Vector3d best_n = Eigen::Vector3d::UnitZ();
  double best_d = 0.0;
  for (int it = 0; it < kIterations; ++it) {
    const Eigen::Vector3d& a = cand[next(cand.size())];
    const Eigen::Vector3d& b = cand[next(cand.size())];
    const Eigen::Vector3d& c = cand[next(cand.size())];
    Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() < 1e-6) continue;
    n.normalize();
    if (n.z() < 0) n = -n;
    if (n.z() < min_cos) continue;
    const double d = -n.dot(a);
    std::size_t count = 0;
    for (const Eigen::Vector3d& p : cand) count += std::fabs(n.dot(p) + d) < threshold ? 1 : 0;
    if (count > best) best = count, best_n = n, best_d = d;
  }
  if (best < kMinInliers) return g;
  std::vector<Eigen::Vector3d> in;
  for (const Eigen::Vector3d& p : cand)
    if (std::fabs(best_n.dot(p) + best_d) < threshold) in.push_back(p);
  Eigen::Vector3d n;
  double d;
  if (!fitPlane(in, n, d) || n.z() < min_cos) n = best_n, d = best_d;
  g.found = true;
  g.inliers = in.size();
  g.level = Eigen::Quaterniond::FromTwoVectors(n, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  g.height = d;
  return g;
}

}  // namespace metricmap
