// LineSegment and the (r, alpha) fit against hand-computed cases and a numeric Jacobian.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "metricmap/lines/line_segment.h"

namespace metricmap {
namespace {

LineSegment seg(double x0, double y0, double x1, double y1) {
  LineSegment s;
  s.start = {x0, y0};
  s.end = {x1, y1};
  return s;
}

}  // namespace

TEST(LineSegment, HorizontalAndVertical) {
  const LineSegment h = seg(0, 1, 4, 1);
  EXPECT_DOUBLE_EQ(h.length(), 4.0);
  EXPECT_DOUBLE_EQ(h.angle(), 0.0);
  EXPECT_DOUBLE_EQ(h.signedDistance({2, 3}),
                   -2.0);  // u = [0, -1]: left of the direction is negative
  EXPECT_DOUBLE_EQ(h.signedDistance({2, -1}), 2.0);
  EXPECT_DOUBLE_EQ(h.distance({2, 3}), 2.0);
  const LineSegment v = seg(1, 0, 1, -3);
  EXPECT_DOUBLE_EQ(v.length(), 3.0);
  EXPECT_DOUBLE_EQ(v.angle(), -M_PI / 2);
  EXPECT_DOUBLE_EQ(v.signedDistance({3, -1}), -2.0);  // u = [-1, 0]
  EXPECT_DOUBLE_EQ(v.signedDistance({0, 5}), 1.0);
  EXPECT_NEAR(h.angleTo(v), -M_PI / 2, 1e-15);
}

TEST(LineSegment, AnglesAcrossPi) {
  const LineSegment a = seg(0, 0, -1, 1e-9);   // just below pi
  const LineSegment b = seg(0, 0, -1, -1e-9);  // just above -pi
  EXPECT_NEAR(a.angle(), M_PI, 1e-8);
  EXPECT_NEAR(b.angle(), -M_PI, 1e-8);
  EXPECT_NEAR(a.angleTo(b), 2e-9, 1e-12);  // wrapped: a tiny turn, not 2 pi
  EXPECT_NEAR(b.angleTo(a), -2e-9, 1e-12);
  EXPECT_DOUBLE_EQ(seg(0, 0, -1, 0).angle(), M_PI);  // (-pi, pi]: exactly pi stays pi
  EXPECT_DOUBLE_EQ(normalizeAngle(-M_PI), M_PI);
  EXPECT_DOUBLE_EQ(normalizeAngle(3 * M_PI), M_PI);
  EXPECT_NEAR(normalizeAngle(2 * M_PI + 0.25), 0.25, 1e-15);
}

TEST(LineSegment, ZeroLength) {
  const LineSegment z = seg(1, 2, 1, 2);
  EXPECT_EQ(z.length(), 0.0);
  EXPECT_EQ(z.angle(), 0.0);
  EXPECT_EQ(z.normal(), Eigen::Vector2d::Zero());
  EXPECT_DOUBLE_EQ(z.signedDistance({4, 6}), 5.0);
  EXPECT_DOUBLE_EQ(z.distance({1, 2}), 0.0);
}

TEST(LineSegment, DistanceVarianceIsNormalProjection) {
  const LineSegment h = seg(0, 0, 2, 0);  // u = [0, -1]
  Eigen::Matrix2d c;
  c << 4.0, 1.0, 1.0, 9.0;
  EXPECT_DOUBLE_EQ(h.distanceVariance(c), 9.0);
  const LineSegment d = seg(0, 0, 1, 1);  // u = [1, -1] / sqrt 2
  EXPECT_NEAR(d.distanceVariance(c), (4.0 - 2.0 + 9.0) / 2.0, 1e-12);
}

TEST(LineFit, HandCases) {
  // Points on y = 2 (normal up): r = 2, alpha = pi/2.
  const LineFit f = fitLine({{-1, 2}, {0, 2}, {3, 2}}, {});
  EXPECT_NEAR(f.r, 2.0, 1e-12);
  EXPECT_NEAR(f.alpha, M_PI / 2, 1e-12);
  // Points on x = -3: r = 3, normal points to -x (alpha = pi).
  const LineFit g = fitLine({{-3, 0}, {-3, 1}, {-3, 5}}, {});
  EXPECT_NEAR(g.r, 3.0, 1e-12);
  EXPECT_NEAR(std::fabs(g.alpha), M_PI, 1e-12);
}

TEST(LineFit, CovarianceMatchesNumericJacobian) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<Eigen::Vector2d> pts;
  std::vector<Eigen::Matrix2d> covs;
  for (int i = 0; i < 25; ++i) {
    const double t = -1.0 + 0.08 * i;
    pts.emplace_back(1.5 + 0.3 * t + noise(rng), -0.5 + t + noise(rng));
    covs.push_back(polarPointCovariance(pts.back().norm(),
                                        std::atan2(pts.back().y(), pts.back().x()), 0.02, 0.005));
  }
  const LineFit f = fitLine(pts, covs);
  Eigen::Matrix2d numeric = Eigen::Matrix2d::Zero();
  const double h = 1e-7;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    Eigen::Matrix2d j;
    for (int a = 0; a < 2; ++a) {
      auto plus = pts, minus = pts;
      plus[i][a] += h;
      minus[i][a] -= h;
      const LineFit fp = fitLine(plus, {}), fm = fitLine(minus, {});
      j(0, a) = (fp.r - fm.r) / (2 * h);
      j(1, a) = normalizeAngle(fp.alpha - fm.alpha) / (2 * h);
    }
    numeric += j * covs[i] * j.transpose();
  }
  EXPECT_LT((f.cov - numeric).norm(), 1e-6 * numeric.norm());
  EXPECT_GT(f.cov(0, 0), 0.0);
  EXPECT_GT(f.cov(1, 1), 0.0);
}

TEST(LineFit, PolarCovariance) {
  // Along x (bearing 0): range noise on x, bearing noise times range on y.
  const Eigen::Matrix2d c = polarPointCovariance(2.0, 0.0, 0.1, 0.01);
  EXPECT_NEAR(c(0, 0), 0.01, 1e-15);
  EXPECT_NEAR(c(1, 1), 4.0 * 1e-4, 1e-15);
  EXPECT_NEAR(c(0, 1), 0.0, 1e-15);
}

}  // namespace metricmap
