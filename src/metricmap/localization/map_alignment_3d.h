#pragma once
/// \file map_alignment_3d.h
/// \brief A scan aligned to the fixed map from a predicted pose: the toolkit's robust
/// point-to-point ICP, coarse then fine correspondence distance, and the share of the scan's
/// points that then lie on the map (the overlap that says whether the match holds).

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "metricmap/registration/point_to_point_icp.h"
#include "metricmap/registration/voxel_hash_map.h"

namespace metricmap {

struct MapAlignmentParams {
  double coarse_threshold = 1.5;  ///< m
  double fine_threshold = 0.5;    ///< m
  int iterations = 30;            ///< per stage
  double overlap_distance = 0.5;  ///< m
};

struct MapAlignment3D {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< sensor -> map
  double overlap = 0.0;  ///< share of the scan's points within overlap_distance of the map
  double rmse = 0.0;     ///< RMS distance of those points (m)
};

/// \brief Align `scan` (sensor frame) to `map` from `initial`: one ICP stage at the coarse
/// threshold, one at the fine.
MapAlignment3D alignToMap(const std::vector<Eigen::Vector3d>& scan, const VoxelHashMap& map,
                          const Eigen::Isometry3d& initial, const MapAlignmentParams& params,
                          PointToPointIcpWorkspace* workspace = nullptr);

/// \brief Share of `scan`'s points (at `pose`) within `distance` of the map, and their RMS.
MapAlignment3D mapOverlap(const std::vector<Eigen::Vector3d>& scan, const VoxelHashMap& map,
                          const Eigen::Isometry3d& pose, double distance);

}  // namespace metricmap
