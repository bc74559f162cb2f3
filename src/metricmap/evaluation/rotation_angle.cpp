#include "metricmap/evaluation/rotation_angle.h"

#include <cmath>

namespace metricmap {

double rotationAngle(const Eigen::Matrix3d& r) {
  const Eigen::Vector3d vee(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));
  return std::atan2(0.5 * vee.norm(), 0.5 * (r.trace() - 1.0));
}

double rotationAngleDeg(const Eigen::Matrix3d& r) {
  constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
  return rotationAngle(r) * kDegPerRad;
}

}  // namespace metricmap
