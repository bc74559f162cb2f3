#include "metricmap/registration/point_to_point_icp.h"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "metricmap/detail/parallel.h"
#include "metricmap/detail/thread_team.h"
#include "metricmap/registration/se3.h"

namespace metricmap {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct NormalEquations {
  Matrix6d h = Matrix6d::Zero();
  Vector6d g = Vector6d::Zero();
  std::size_t pairs = 0;
};

// -[p]x: the derivative of (w x p) with respect to w, negated sign folded in.
Eigen::Matrix3d minusHat(const Eigen::Vector3d& p) {
  Eigen::Matrix3d m;
  m << 0, p.z(), -p.y(), -p.z(), 0, p.x(), p.y(), -p.x(), 0;
  return m;
}

// Source points per block of the normal equations: the blocks' sums are added in block order,
// whatever thread computed them.
constexpr std::size_t kBlock = 256;

// Pairs and normal equations of source[begin, end) at pose t. Residual in the sensor frame
// r = R^T (t p - q); its Jacobian for the right perturbation (dt, dtheta) is [I, -[p]x].
void addPairs(const std::vector<Eigen::Vector3d>& source, std::size_t begin, std::size_t end,
              const VoxelHashMap& map, const Eigen::Isometry3d& t, double threshold,
              std::vector<VoxelHashMap::Neighbourhood>& cache, NormalEquations& ne) {
  const Eigen::Matrix3d rt = t.linear().transpose();
  const double kernel2 = (threshold / 3.0) * (threshold / 3.0);
  Eigen::Vector3d q;
  for (std::size_t i = begin; i < end; ++i) {
    const Eigen::Vector3d& p = source[i];
    const Eigen::Vector3d w = t * p;
    if (!map.nearestCached(w, threshold, cache[i], q)) continue;
    const Eigen::Vector3d r = rt * (w - q);
    const double e2 = r.squaredNorm() / kernel2;
    const double weight = 1.0 / ((1.0 + e2) * (1.0 + e2));
    const Eigen::Matrix3d j = minusHat(p);  // rotation part; translation part is I
    ne.h.topLeftCorner<3, 3>() += weight * Eigen::Matrix3d::Identity();
    ne.h.topRightCorner<3, 3>().noalias() += weight * j;
    ne.h.bottomRightCorner<3, 3>().noalias() += weight * j.transpose() * j;
    ne.g.head<3>() += weight * r;
    ne.g.tail<3>().noalias() += weight * j.transpose() * r;
    ++ne.pairs;
  }
}

// fn(b) for every block b of `count`, the blocks split into one contiguous run for each of
// the team's first `used` threads.
template <class Fn>
void forBlocks(ThreadTeam& team, unsigned used, std::size_t count, Fn fn) {
  team.run([&](unsigned th) {
    if (th >= used) return;
    const auto range = chunkOf(count, used, th);
    for (std::size_t b = range.first; b < range.second; ++b) fn(b);
  });
}

NormalEquations buildSystem(const std::vector<Eigen::Vector3d>& source, const VoxelHashMap& map,
                            const Eigen::Isometry3d& t, double threshold, ThreadTeam& team,
                            unsigned used, std::vector<VoxelHashMap::Neighbourhood>& cache,
                            std::vector<NormalEquations>& blocks) {
  const std::size_t n = source.size(), count = (n + kBlock - 1) / kBlock;
  blocks.assign(count, NormalEquations());
  forBlocks(team, used, count, [&](std::size_t b) {
    addPairs(source, b * kBlock, std::min(n, (b + 1) * kBlock), map, t, threshold, cache,
             blocks[b]);
  });
  NormalEquations ne;
  for (const NormalEquations& b : blocks) {
    ne.h += b.h;
    ne.g += b.g;
    ne.pairs += b.pairs;
  }
  ne.h.bottomLeftCorner<3, 3>() = ne.h.topRightCorner<3, 3>().transpose();
  return ne;
}

// Point-to-plane information of the pairs of source[begin, end) at pose t (sensor frame,
// rotation scaled by 1/scale).
Matrix6d surfaceInformation(const std::vector<Eigen::Vector3d>& source, std::size_t begin,
                            std::size_t end, const VoxelHashMap& map, const Eigen::Isometry3d& t,
                            double threshold, double inv_scale,
                            std::vector<VoxelHashMap::Neighbourhood>& cache) {
  Matrix6d info = Matrix6d::Zero();
  const Eigen::Matrix3d rt = t.linear().transpose();
  Eigen::Vector3d q;
  std::int32_t v = -1;
  for (std::size_t i = begin; i < end; ++i) {
    const Eigen::Vector3d& p = source[i];
    if (!map.nearestCached(t * p, threshold, cache[i], q, &v)) continue;
    const int size = map.voxelSize(v);
    if (size < 6) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int k = 0; k < size; ++k) mean += map.voxelPoint(v, k);
    mean /= static_cast<double>(size);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int k = 0; k < size; ++k) {
      const Eigen::Vector3d d = map.voxelPoint(v, k) - mean;
      cov.noalias() += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(cov);
    // Only surfaces: the smallest spread far below the middle one. (A voxel across an edge,
    // or a few points narrow along one axis, would give a normal no surface has.)
    if (!(eig.eigenvalues()(0) < 0.02 * eig.eigenvalues()(1))) continue;
    const Eigen::Vector3d n = rt * eig.eigenvectors().col(0);
    Vector6d j;
    j.head<3>() = n;
    j.tail<3>() = p.cross(n) * inv_scale;
    info.noalias() += j * j.transpose();
  }
  return info;
}

}  // namespace

PointToPointIcpWorkspace::PointToPointIcpWorkspace() = default;
PointToPointIcpWorkspace::~PointToPointIcpWorkspace() = default;
PointToPointIcpWorkspace::PointToPointIcpWorkspace(const PointToPointIcpWorkspace&) {}
PointToPointIcpWorkspace& PointToPointIcpWorkspace::operator=(const PointToPointIcpWorkspace&) {
  return *this;
}
PointToPointIcpWorkspace::PointToPointIcpWorkspace(PointToPointIcpWorkspace&&) noexcept = default;
PointToPointIcpWorkspace& PointToPointIcpWorkspace::operator=(PointToPointIcpWorkspace&&) noexcept =
    default;

PointToPointIcpResult alignPointToPoint(const std::vector<Eigen::Vector3d>& source,
                                        const VoxelHashMap& map, const Eigen::Isometry3d& initial,
                                        const PointToPointIcpParams& params,
                                        PointToPointIcpWorkspace* workspace) {
  PointToPointIcpResult res;
  res.pose = initial;
  if (source.empty() || map.empty()) return res;
  PointToPointIcpWorkspace own;
  PointToPointIcpWorkspace& ws = workspace != nullptr ? *workspace : own;
  std::vector<VoxelHashMap::Neighbourhood>& cache = ws.neighbourhoods;
  cache.assign(source.size(), VoxelHashMap::Neighbourhood());
  const std::size_t n = source.size(), count = (n + kBlock - 1) / kBlock;
  // At least 2 blocks (512 points) per thread; the team is kept in the workspace, so a step
  // costs a wake-up, not a thread start.
  // The team only grows: a scan with fewer points leaves the extra threads idle.
  const unsigned used = resolveThreads(params.threads, count, 2);
  if (!ws.team || ws.team->size() < used) ws.team = std::make_unique<ThreadTeam>(used);
  ThreadTeam& team = *ws.team;
  std::vector<NormalEquations> blocks;
  for (res.iterations = 0; res.iterations < params.max_iterations;) {
    const NormalEquations ne =
        buildSystem(source, map, res.pose, params.threshold, team, used, cache, blocks);
    if (ne.pairs < 6) break;
    const Vector6d step = ne.h.ldlt().solve(-ne.g);
    if (!step.allFinite()) break;
    res.pose = res.pose * se3Exp(step);
    ++res.iterations;
    if (step.norm() < params.convergence) {
      res.converged = true;
      break;
    }
  }
  std::vector<std::size_t> paired(count, 0);
  forBlocks(team, used, count, [&](std::size_t b) {
    Eigen::Vector3d q;
    for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
      paired[b] += map.nearestCached(res.pose * source[i], params.threshold, cache[i], q);
    }
  });
  res.correspondences = 0;
  for (const std::size_t c : paired) res.correspondences += c;
  if (params.degeneracy_ratio <= 0.0 || res.correspondences < 6) return res;
  double sq = 0.0;
  for (const Eigen::Vector3d& p : source) sq += p.squaredNorm();

  // Unobservable directions: hold them at the initial guess.
  const double scale = std::max(1.0, std::sqrt(sq / static_cast<double>(source.size())));
  std::vector<Matrix6d> infos(count);
  forBlocks(team, used, count, [&](std::size_t b) {
    infos[b] = surfaceInformation(source, b * kBlock, std::min(n, (b + 1) * kBlock), map, res.pose,
                                  params.threshold, 1.0 / scale, cache);
  });
  Matrix6d info = Matrix6d::Zero();
  for (const Matrix6d& m : infos) info += m;
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(info);
  const Vector6d lambda = eig.eigenvalues();  // ascending
  if (!(lambda(5) > 0.0)) return res;
  res.eigen_ratio = lambda(0) / lambda(5);
  Eigen::Isometry3d correction;
  correction.matrix() = initial.matrix().inverse() * res.pose.matrix();
  Vector6d xi = se3Log(correction);
  xi.tail<3>() *= scale;
  for (int i = 0; i < 6; ++i) {
    if (lambda(i) >= params.degeneracy_ratio * lambda(5)) continue;
    ++res.degenerate_directions;
    const Vector6d v = eig.eigenvectors().col(i);
    xi -= v * v.dot(xi);
  }
  if (res.degenerate_directions > 0) {
    xi.tail<3>() /= scale;
    res.pose = initial * se3Exp(xi);
  }
  return res;
}

}  // namespace metricmap
