#include "metricmap/slam/scan_matcher_2d.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Dense>

namespace metricmap {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::int64_t cellOf(double v, double inv_res) {
  return static_cast<std::int64_t>(std::floor(v * inv_res));
}

}  // namespace

double angularSearchStep(double resolution, const std::vector<Eigen::Vector2f>& points) {
  double d = 0.0;
  for (const Eigen::Vector2f& p : points) d = std::max(d, static_cast<double>(p.norm()));
  const double one_degree = kPi / 180.0;
  if (d <= resolution) return one_degree;
  return std::min(one_degree, std::acos(1.0 - resolution * resolution / (2.0 * d * d)));
}

double scoreAt(const MatchGrid& grid, const std::vector<Eigen::Vector2f>& points,
               const Pose2D& pose) {
  if (points.empty()) return 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta), inv = 1.0 / grid.resolution();
  double sum = 0.0;
  for (const Eigen::Vector2f& p : points) {
    const double x = pose.x + c * p.x() - s * p.y(), y = pose.y + s * p.x() + c * p.y();
    sum += grid.probability(cellOf(x, inv), cellOf(y, inv));
  }
  return sum / static_cast<double>(points.size());
}

ScanMatch2D correlativeSearch(const MatchGrid& grid, const std::vector<Eigen::Vector2f>& points,
                              const Pose2D& initial, double linear_window, double angular_window,
                              double angular_step) {
  ScanMatch2D best{initial, scoreAt(grid, points, initial)};
  if (points.empty()) return best;
  const double res = grid.resolution(), inv = 1.0 / res;
  const int n = static_cast<int>(std::floor(linear_window / res + 1e-9));
  const int m =
      angular_step > 0.0 ? static_cast<int>(std::floor(angular_window / angular_step + 1e-9)) : 0;
  double best_sum = best.score * static_cast<double>(points.size());
  long best_dist = 0;
  std::vector<std::int64_t> ci(points.size()), cj(points.size());
  for (int a = -m; a <= m; ++a) {
    const double theta = initial.theta + a * angular_step;
    const double c = std::cos(theta), s = std::sin(theta);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector2f& p = points[k];
      ci[k] = cellOf(initial.x + c * p.x() - s * p.y(), inv);
      cj[k] = cellOf(initial.y + s * p.x() + c * p.y(), inv);
    }
    for (int dy = -n; dy <= n; ++dy)
      for (int dx = -n; dx <= n; ++dx) {
        double sum = 0.0;
        for (std::size_t k = 0; k < points.size(); ++k)
          sum += grid.probability(ci[k] + dx, cj[k] + dy);
        const long dist =
            static_cast<long>(dx) * dx + static_cast<long>(dy) * dy + static_cast<long>(a) * a;
        if (sum > best_sum || (sum == best_sum && dist < best_dist)) {
          best_sum = sum;
          best_dist = dist;
          best.pose = {initial.x + dx * res, initial.y + dy * res, theta};
        }
      }
  }
  best.score = best_sum / static_cast<double>(points.size());
  return best;
}

ScanMatch2D refinePose(const MatchGrid& grid, const std::vector<Eigen::Vector2f>& points,
                       const Pose2D& initial, const Pose2D& prior, double translation_weight,
                       double rotation_weight, int iterations, bool cubic,
                       const WeakDirectionPrior* weak) {
  Pose2D x = initial;
  if (!points.empty()) {
    const double w_occ = 1.0 / std::sqrt(static_cast<double>(points.size()));
    const double wt2 = translation_weight * translation_weight;
    const double wr2 = rotation_weight * rotation_weight;
    for (int it = 0; it < iterations; ++it) {
      Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
      Eigen::Vector3d g = Eigen::Vector3d::Zero();
      const double c = std::cos(x.theta), s = std::sin(x.theta);
      for (const Eigen::Vector2f& p : points) {
        const double px = p.x(), py = p.y();
        double gx, gy;
        const double wx = x.x + c * px - s * py, wy = x.y + s * px + c * py;
        const double m =
            cubic ? grid.interpolateCubic(wx, wy, gx, gy) : grid.interpolate(wx, wy, gx, gy);
        const double r = (1.0 - m) * w_occ;
        const Eigen::Vector3d j(-gx * w_occ, -gy * w_occ,
                                -(gx * (-s * px - c * py) + gy * (c * px - s * py)) * w_occ);
        h += j * j.transpose();
        g += j * r;
      }
      if (weak) {  // the data term's weak translation directions, at this iterate
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(h.topLeftCorner<2, 2>());
        const Eigen::Vector2d away(x.x - weak->target.x(), x.y - weak->target.y());
        for (int k = 0; k < 2; ++k) {
          if (es.eigenvalues()(k) >= weak->min_information) continue;
          const Eigen::Vector2d v = es.eigenvectors().col(k);
          const Eigen::Matrix2d p = weak->weight * weak->weight * v * v.transpose();
          h.topLeftCorner<2, 2>() += p;
          g.head<2>() += p * away;
        }
      }
      double dtheta = x.theta - prior.theta;
      dtheta = std::remainder(dtheta, 2.0 * kPi);
      h(0, 0) += wt2;
      h(1, 1) += wt2;
      h(2, 2) += wr2;
      g(0) += wt2 * (x.x - prior.x);
      g(1) += wt2 * (x.y - prior.y);
      g(2) += wr2 * dtheta;
      const Eigen::Vector3d step = h.ldlt().solve(-g);
      if (!step.allFinite()) break;
      x.x += step(0);
      x.y += step(1);
      x.theta += step(2);
      if (step.cwiseAbs().maxCoeff() < 1e-6) break;
    }
  }
  x.theta = std::remainder(x.theta, 2.0 * kPi);
  return {x, scoreAt(grid, points, x)};
}

}  // namespace metricmap
