#pragma once
/// \file trajectory.h
/// \brief Trajectories in TUM form ("timestamp tx ty tz qx qy qz qw" per line). KITTI pose
/// files are read by datasets/kitti_sequence.h.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace metricmap {

/// \brief The first `frames` poses (sensor -> world) of a TUM trajectory; blank lines and
/// lines starting with '#' are skipped; frame k takes the k-th pose line.
/// \throws InputError naming the file and line for a malformed line, a zero quaternion or too
/// few poses
std::vector<Eigen::Isometry3d> readTumTrajectory(const std::string& path, std::size_t frames);

}  // namespace metricmap
