#include "metricmap/registration/deskew.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "metricmap/registration/se3.h"

namespace metricmap {

std::vector<Eigen::Vector3d> deskewScan(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<double>& times,
                                        const Eigen::Isometry3d& motion, double reference) {
  if (times.size() != points.size()) {
    throw std::invalid_argument("deskew: " + std::to_string(times.size()) + " times for " +
                                std::to_string(points.size()) + " points");
  }
  const Vector6d twist = se3Log(motion);
  std::vector<Eigen::Vector3d> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(times[i])) {
      throw std::invalid_argument("deskew: time of point " + std::to_string(i) + " is not finite");
    }
    out[i] = se3Exp((times[i] - reference) * twist) * points[i];
  }
  return out;
}

std::vector<double> azimuthTimes(const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> t(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    t[i] = (M_PI - std::atan2(points[i].y(), points[i].x())) / (2.0 * M_PI);
  }
  return t;
}

}  // namespace metricmap
