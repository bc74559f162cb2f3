#include "metricmap/lines/line_segment.h"

#include <cmath>

namespace metricmap {

double normalizeAngle(double angle) {
  double a = std::remainder(angle, 2.0 * M_PI);  // [-pi, pi]
  if (a <= -M_PI) a += 2.0 * M_PI;
  return a;
}

double LineSegment::angle() const {
  const Eigen::Vector2d d = end - start;
  if (d.squaredNorm() == 0.0) return 0.0;
  return normalizeAngle(std::atan2(d.y(), d.x()));
}

Eigen::Vector2d LineSegment::normal() const {
  const Eigen::Vector2d d = end - start;
  const double l = d.norm();
  if (l == 0.0) return Eigen::Vector2d::Zero();
  return Eigen::Vector2d(d.y() / l, -d.x() / l);
}

double LineSegment::signedDistance(const Eigen::Vector2d& p) const {
  if (length() == 0.0) return (p - start).norm();
  return normal().dot(p - start);
}

double LineSegment::distance(const Eigen::Vector2d& p) const {
  return std::fabs(signedDistance(p));
}

double LineSegment::distanceVariance(const Eigen::Matrix2d& cov) const {
  const Eigen::Vector2d u = normal();
  return u.dot(cov * u);
}

double LineSegment::angleTo(const LineSegment& next) const {
  return normalizeAngle(next.angle() - angle());
}

Eigen::Matrix2d polarPointCovariance(double range, double bearing, double sigma_range,
                                     double sigma_bearing) {
  Eigen::Matrix2d j;
  j << std::cos(bearing), -range * std::sin(bearing), std::sin(bearing), range * std::cos(bearing);
  const Eigen::Matrix2d s =
      Eigen::Vector2d(sigma_range * sigma_range, sigma_bearing * sigma_bearing).asDiagonal();
  return j * s * j.transpose();
}

LineFit fitLine(const std::vector<Eigen::Vector2d>& xy, const std::vector<Eigen::Matrix2d>& covs) {
  LineFit fit;
  const std::size_t n = xy.size();
  if (n == 0) return fit;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : xy) mean += p;
  mean /= static_cast<double>(n);
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (const auto& p : xy) {
    const Eigen::Vector2d d = p - mean;
    sxx += d.x() * d.x();
    syy += d.y() * d.y();
    sxy += d.x() * d.y();
  }
  // Normal angle minimising the sum of squared orthogonal distances.
  const double a = -2.0 * sxy, b = syy - sxx;
  double alpha = 0.5 * std::atan2(a, b);
  double r = mean.x() * std::cos(alpha) + mean.y() * std::sin(alpha);
  if (r < 0.0) {  // keep r >= 0: the normal turns by pi
    r = -r;
    alpha += M_PI;
  }
  fit.r = r;
  fit.alpha = normalizeAngle(alpha);
  if (covs.size() != n) return fit;
  // Jacobian of (r, alpha) with respect to each point, then J C J^T summed over points.
  const double denom = a * a + b * b;
  const double ca = std::cos(alpha), sa = std::sin(alpha);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d d = xy[i] - mean;
    Eigen::Matrix2d jac;  // rows: r, alpha; columns: x_i, y_i
    double dalpha_dx = 0.0, dalpha_dy = 0.0;
    if (denom > 0.0) {
      const double da_dx = -2.0 * d.y(), da_dy = -2.0 * d.x();
      const double db_dx = -2.0 * d.x(), db_dy = 2.0 * d.y();
      dalpha_dx = 0.5 * (b * da_dx - a * db_dx) / denom;
      dalpha_dy = 0.5 * (b * da_dy - a * db_dy) / denom;
    }
    const double dr_dalpha = -mean.x() * sa + mean.y() * ca;
    jac(0, 0) = ca / static_cast<double>(n) + dr_dalpha * dalpha_dx;
    jac(0, 1) = sa / static_cast<double>(n) + dr_dalpha * dalpha_dy;
    jac(1, 0) = dalpha_dx;
    jac(1, 1) = dalpha_dy;
    fit.cov += jac * covs[i] * jac.transpose();
  }
  return fit;
}

}  // namespace metricmap
