#pragma once
/// \file voxel_downsample.h
/// \brief One point per voxel (the first one met), on plain arrays of Eigen vectors or on a PCL
/// cloud, optionally within a range window.

#include <cstddef>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>

namespace metricmap {

using Points3d = std::vector<Eigen::Vector3d>;

/// \brief The first point of each `voxel`-sized cell, in input order; `kept` (optional)
/// receives the input index of each kept point.
/// \throws std::invalid_argument when `voxel` is not a finite number > 0
/// \throws CapacityError when a point's cell lies outside the 21-bit cell range
Points3d voxelDownsample(const Points3d& points, double voxel, std::vector<int>* kept = nullptr);
/// \brief The same into `out` (cleared first; its capacity is reused). `out` must not be
/// `points`.
void voxelDownsample(const Points3d& points, double voxel, Points3d& out,
                     std::vector<int>* kept = nullptr);

/// \brief What a windowed downsampling saw.
struct RangeWindowCounts {
  std::size_t finite = 0;    ///< points with finite coordinates
  std::size_t in_range = 0;  ///< of those, with min_range <= |p| <= max_range
};
/// \brief voxelDownsample() of the finite points whose range lies in [min_range, max_range], in
/// one pass and without a copy of the window: `out` (cleared first) receives the first point of
/// each cell, `kept` (optional) their indices in the input.
/// \throws as voxelDownsample()
RangeWindowCounts downsampleInRange(const Points3d& points, double min_range, double max_range,
                                    double voxel, Points3d& out, std::vector<int>* kept = nullptr);
RangeWindowCounts downsampleInRange(const pcl::PointCloud<pcl::PointXYZ>& points, double min_range,
                                    double max_range, double voxel, Points3d& out,
                                    std::vector<int>* kept = nullptr);

}  // namespace metricmap
