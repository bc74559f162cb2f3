#pragma once
/// \file line_segment.h
/// \brief A straight segment of an ordered 2D scan, with its least-squares line and covariance.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace metricmap {

/// \brief Wrap an angle to (-pi, pi].
double normalizeAngle(double angle);

/// \brief Least-squares line in normal form x cos(alpha) + y sin(alpha) = r, r >= 0, with the
/// 2x2 covariance of (r, alpha) propagated from the points' covariances.
struct LineFit {
  double r = 0.0;
  double alpha = 0.0;                             ///< direction of the line's normal, (-pi, pi]
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();  ///< covariance of (r, alpha)
};

/// \brief A segment between two scan points. Indices are beam indices of the scan.
struct LineSegment {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  ///< first point (scan order)
  Eigen::Vector2d end = Eigen::Vector2d::Zero();    ///< last point
  int first_index = 0;                              ///< beam index of start
  int last_index = 0;                               ///< beam index of end
  std::size_t points = 0;                           ///< valid points the segment stands for
  LineFit fit;

  /// \brief Distance from start to end.
  double length() const { return (end - start).norm(); }
  /// \brief Direction of start -> end, (-pi, pi]; 0 for a zero-length segment.
  double angle() const;
  /// \brief Unit normal u = [(y_e - y_s), -(x_e - x_s)] / length (u_perp);
  /// zero for a zero-length segment.
  Eigen::Vector2d normal() const;
  /// \brief u . (p - start): positive to the right of start -> end. For a zero-length segment,
  /// the distance to start (never negative).
  double signedDistance(const Eigen::Vector2d& p) const;
  /// \brief |signedDistance(p)|.
  double distance(const Eigen::Vector2d& p) const;
  /// \brief Variance of signedDistance(p) for a point with covariance `cov`, endpoints exact:
  /// u^T cov u.
  double distanceVariance(const Eigen::Matrix2d& cov) const;
  /// \brief next.angle() - angle(), wrapped to (-pi, pi].
  double angleTo(const LineSegment& next) const;
};

/// \brief Covariance of a point measured at `range` and `bearing` with standard deviations
/// sigma_range and sigma_bearing (polar -> Cartesian Jacobian).
Eigen::Matrix2d polarPointCovariance(double range, double bearing, double sigma_range,
                                     double sigma_bearing);

/// \brief Fit (r, alpha) to points by total least squares and propagate their covariances
/// (one 2x2 matrix per point) to (r, alpha) through the analytic Jacobian.
/// \param[in] xy n points; \param[in] covs n covariances (may be empty: cov stays zero)
LineFit fitLine(const std::vector<Eigen::Vector2d>& xy, const std::vector<Eigen::Matrix2d>& covs);

}  // namespace metricmap
