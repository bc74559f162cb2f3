#pragma once
/// \file trajectory.h
/// \brief A trajectory: stamped poses of one sensor (sensor -> world), in acquisition order.

#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

namespace metricmap {

/// \brief Poses (sensor -> world) with optional time stamps (seconds). `stamps` is empty when
/// the trajectory has none, else it has one stamp per pose.
struct Trajectory {
  std::vector<double> stamps;
  std::vector<Eigen::Isometry3d> poses;

  std::size_t size() const { return poses.size(); }
  bool empty() const { return poses.empty(); }
  bool hasStamps() const { return !stamps.empty(); }
};

}  // namespace metricmap
