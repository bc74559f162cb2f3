#include <cmath>
#include <limits>

#include "metricmap/detail/parallel.h"
#include "metricmap/distance/distance_field.h"
#include "metricmap/distance/distance_work.h"

namespace metricmap {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEdge = 1e-9;  ///< voxel units a point may lie beyond the outer centres

/// Cell of an interpolation axis: lower index and the fraction towards the next centre. An
/// axis of one voxel is constant (fraction 0) over that voxel.
bool axisCell(double u, std::size_t n, std::size_t& i0, double& t) {
  if (!std::isfinite(u)) return false;
  if (n == 1) {
    i0 = 0;
    t = 0.0;
    return std::abs(u) <= 0.5;
  }
  const double top = static_cast<double>(n - 1);
  if (u < -kEdge || u > top + kEdge) return false;
  const double c = std::min(std::max(u, 0.0), top);
  i0 = std::min(static_cast<std::size_t>(c), n - 2);
  t = c - static_cast<double>(i0);
  return true;
}

}  // namespace

DistanceQuery DistanceField::query(const Eigen::Vector3d& p) const {
  DistanceQuery q;
  const Eigen::Vector3d u = (p - box_.origin) / box_.resolution;
  std::size_t i0[3] = {0, 0, 0};
  double t[3] = {0, 0, 0};
  const int dims = box_.dimensions;
  for (int a = 0; a < dims; ++a) {
    if (!axisCell(u[a], box_.shape[a], i0[a], t[a])) {
      q.distance = kNaN;
      q.gradient.setConstant(kNaN);
      return q;
    }
  }
  q.inside = true;
  // the corners present on each axis: 2, or 1 for a single-voxel (or 2D z) axis
  int steps[3];
  for (int a = 0; a < 3; ++a) steps[a] = box_.shape[a] > 1 && a < dims ? 2 : 1;
  double value = 0.0;
  Eigen::Vector3d grad = Eigen::Vector3d::Zero();
  for (int a = 0; a < steps[0]; ++a) {
    for (int b = 0; b < steps[1]; ++b) {
      for (int c = 0; c < steps[2]; ++c) {
        const double v = field_[index(i0[0] + a, i0[1] + b, i0[2] + c)];
        const double wx = a ? t[0] : 1 - t[0], wy = b ? t[1] : 1 - t[1], wz = c ? t[2] : 1 - t[2];
        const double sx = steps[0] == 2 ? (a ? 1 : -1) : 0, sy = steps[1] == 2 ? (b ? 1 : -1) : 0,
                     sz = steps[2] == 2 ? (c ? 1 : -1) : 0;
        const double wx1 = steps[0] == 2 ? wx : 1, wy1 = steps[1] == 2 ? wy : 1,
                     wz1 = steps[2] == 2 ? wz : 1;
        value += wx1 * wy1 * wz1 * v;
        grad.x() += sx * wy1 * wz1 * v;
        grad.y() += wx1 * sy * wz1 * v;
        grad.z() += wx1 * wy1 * sz * v;
      }
    }
  }
  q.distance = value;
  q.gradient = grad / box_.resolution;
  return q;
}

void DistanceField::queryMany(const double* xyz, std::size_t count, double* distance,
                              double* gradient) const {
  const unsigned threads = resolveThreads(params_.threads, count, 4096);
  parallelRun(threads, [&](unsigned th) {
    const auto [begin, end] = chunkOf(count, threads, th);
    for (std::size_t n = begin; n < end; ++n) {
      const DistanceQuery q = query(Eigen::Vector3d(xyz[3 * n], xyz[3 * n + 1], xyz[3 * n + 2]));
      distance[n] = q.distance;
      if (gradient != nullptr) {
        for (int a = 0; a < 3; ++a) gradient[3 * n + a] = q.gradient[a];
      }
    }
  });
}

bool DistanceField::isObserved(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d u = (p - box_.origin) / box_.resolution;
  std::size_t c[3] = {0, 0, 0};
  for (int a = 0; a < box_.dimensions; ++a) {
    const double r = std::floor(u[a] + 0.5);
    if (!std::isfinite(r) || r < 0 || r >= static_cast<double>(box_.shape[a])) return false;
    c[a] = static_cast<std::size_t>(r);
  }
  return box_.state[index(c[0], c[1], c[2])] != kVoxelUnknown;
}

bool DistanceField::nearestObstacle(const Eigen::Vector3d& p, Eigen::Vector3d& obstacle) const {
  const Eigen::Vector3d u = (p - box_.origin) / box_.resolution;
  const int dims = box_.dimensions;
  std::int64_t c[3] = {0, 0, 0};
  for (int a = 0; a < dims; ++a) {
    const double r = std::floor(u[a] + 0.5);
    if (!std::isfinite(r) || r < 0 || r >= static_cast<double>(box_.shape[a])) return false;
    c[a] = static_cast<std::int64_t>(r);
  }
  const std::size_t at = index(c[0], c[1], c[2]);
  const bool border = params_.unknown == UnknownAs::Occupied;
  double d = 0.0;  // voxel units from p's voxel to its nearest obstacle
  if (!work_->site[0][at]) {
    const double f = field_[at];
    if (f >= params_.max_distance) return false;
    d = f / box_.resolution;
  }
  // every obstacle nearer to p than that one lies within d + |p - centre| of p
  const double reach = d + std::sqrt(3.0) / 2 + 1e-9;
  std::int64_t lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    const auto n = static_cast<std::int64_t>(box_.shape[a]);
    const bool wall = border && a < dims;
    if (a >= dims) {
      lo[a] = hi[a] = 0;
      continue;
    }
    lo[a] =
        std::max<std::int64_t>(static_cast<std::int64_t>(std::floor(u[a] - reach)), wall ? -1 : 0);
    hi[a] = std::min<std::int64_t>(static_cast<std::int64_t>(std::ceil(u[a] + reach)),
                                   wall ? n : n - 1);
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
    for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
      for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
        const bool out = x < 0 || y < 0 || z < 0 || x >= static_cast<std::int64_t>(box_.shape[0]) ||
                         y >= static_cast<std::int64_t>(box_.shape[1]) ||
                         z >= static_cast<std::int64_t>(box_.shape[2]);
        if (!out && !work_->site[0][index(x, y, z)]) continue;
        const Eigen::Vector3d o(static_cast<double>(x), static_cast<double>(y),
                                static_cast<double>(z));
        Eigen::Vector3d diff = o - u;
        if (dims == 2) diff.z() = 0;
        const double d2 = diff.squaredNorm();
        if (d2 < best) {
          best = d2;
          obstacle = box_.origin + o * box_.resolution;
        }
      }
    }
  }
  if (dims == 2 && std::isfinite(best)) obstacle.z() = p.z();
  return std::isfinite(best);
}

}  // namespace metricmap
