#pragma once
/// \file edge_error.h
/// \brief Internal to the pose graph (not API): g2o's edge errors as templates, so that the
/// graph's chi² (T = double) and the optimiser's residuals (T = ceres::Jet, in optimize.cpp)
/// are one formula. No Ceres here: Jets find their sin/cos/floor by argument-dependent lookup.

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace metricmap::detail {

inline constexpr double kPi = 3.14159265358979323846;

/// \brief `angle` wrapped to [-π, π) (Ceres' examples' NormalizeAngle, differentiable).
template <typename T>
T wrapAngle(const T& angle) {
  using std::floor;
  const T two_pi(2.0 * kPi);
  return angle - two_pi * floor((angle + T(kPi)) / two_pi);
}

/// \brief SE(2) error of the edge i -> j with measurement z: z⁻¹ (x_i⁻¹ x_j) as (x, y, θ).
/// \param xi, xj poses (x, y, θ)
/// \param z the measurement (x, y, θ)
/// \param e the error (3 values)
template <typename T>
void se2Error(const T* xi, const T* xj, const double* z, T* e) {
  using std::cos;
  using std::sin;
  const T ci = cos(xi[2]);
  const T si = sin(xi[2]);
  const T dx = xj[0] - xi[0];
  const T dy = xj[1] - xi[1];
  // x_i⁻¹ x_j minus the measurement's translation, in x_i's frame ...
  const T tx = ci * dx + si * dy - z[0];
  const T ty = -si * dx + ci * dy - z[1];
  // ... rotated into the measurement's frame.
  const double cz = std::cos(z[2]);
  const double sz = std::sin(z[2]);
  e[0] = cz * tx + sz * ty;
  e[1] = -sz * tx + cz * ty;
  e[2] = wrapAngle(xj[2] - xi[2] - T(z[2]));
}

/// \brief SE(3) error of the edge i -> j with measurement (tz, qz): z⁻¹ (x_i⁻¹ x_j) as
/// (translation, vector part of the quaternion taken with w >= 0), as g2o's EdgeSE3.
/// \param ti, tj translations (3 values); qi, qj unit quaternions in Eigen's order (x, y, z, w)
/// \param tz, qz the measurement, qz unit
/// \param e the error (6 values)
template <typename T>
void se3Error(const T* ti, const T* qi, const T* tj, const T* qj, const Eigen::Vector3d& tz,
              const Eigen::Quaterniond& qz, T* e) {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  using Quat = Eigen::Quaternion<T>;
  const Eigen::Map<const Vec3> pi(ti);
  const Eigen::Map<const Vec3> pj(tj);
  const Eigen::Map<const Quat> qa(qi);
  const Eigen::Map<const Quat> qb(qj);
  const Quat qa_inverse = qa.conjugate();
  const Quat qab = qa_inverse * qb;
  const Vec3 tab = qa_inverse * (pj - pi);
  const Quat qz_inverse = qz.conjugate().template cast<T>();
  const Quat qd = qz_inverse * qab;
  const Vec3 td = qz_inverse * (tab - tz.template cast<T>());
  e[0] = td[0];
  e[1] = td[1];
  e[2] = td[2];
  const T sign = qd.w() < T(0) ? T(-1) : T(1);
  e[3] = sign * qd.x();
  e[4] = sign * qd.y();
  e[5] = sign * qd.z();
}

}  // namespace metricmap::detail
