#include "metricmap/registration/se3.h"

#include <cmath>

namespace metricmap {
namespace {

Eigen::Matrix3d hat(const Eigen::Vector3d& w) {
  Eigen::Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

// V(w) = I + (1 - cos t)/t^2 [w] + (t - sin t)/t^3 [w]^2, with series near t = 0.
Eigen::Matrix3d leftJacobian(const Eigen::Vector3d& w) {
  const double t = w.norm();
  const Eigen::Matrix3d W = hat(w);
  double a, b;
  if (t < 1e-6) {
    a = 0.5 - t * t / 24.0;
    b = 1.0 / 6.0 - t * t / 120.0;
  } else {
    a = (1.0 - std::cos(t)) / (t * t);
    b = (t - std::sin(t)) / (t * t * t);
  }
  return Eigen::Matrix3d::Identity() + a * W + b * W * W;
}

}  // namespace

Eigen::Isometry3d se3Exp(const Vector6d& twist) {
  const Eigen::Vector3d v = twist.head<3>(), w = twist.tail<3>();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  const double angle = w.norm();
  t.linear() = angle < 1e-12 ? Eigen::Matrix3d::Identity()
                             : Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
  t.translation() = leftJacobian(w) * v;
  return t;
}

Vector6d se3Log(const Eigen::Isometry3d& t) {
  const Eigen::AngleAxisd aa(t.linear());
  const Eigen::Vector3d w = aa.angle() * aa.axis();
  Vector6d out;
  out.tail<3>() = w;
  out.head<3>() = leftJacobian(w).inverse() * t.translation();
  return out;
}

}  // namespace metricmap
