#pragma once
/// \file voxel_downsample.h
/// \brief One point per voxel (the first one met), on plain arrays of Eigen vectors.

#include <vector>

#include <Eigen/Core>

namespace metricmap {

using Points3d = std::vector<Eigen::Vector3d>;

/// \brief The first point of each `voxel`-sized cell, in input order; `kept` (optional)
/// receives the input index of each kept point.
/// \throws std::invalid_argument when `voxel` is not a finite number > 0
Points3d voxelDownsample(const Points3d& points, double voxel, std::vector<int>* kept = nullptr);

}  // namespace metricmap
