#pragma once
/// \file scan_registration.h
/// \brief Refining a scan's pose against a map with pcl::IterativeClosestPoint or
/// pcl::GeneralizedIterativeClosestPoint; pose perturbation and pose errors for experiments.

#include <cstddef>
#include <limits>
#include <random>
#include <string>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

namespace metricmap {

enum class RefineMethod { Icp, Gicp };

/// \brief "icp" | "gicp". \throws std::invalid_argument
RefineMethod parseRefineMethod(const std::string& name);

struct RefineParams {
  RefineMethod method = RefineMethod::Icp;
  double max_correspondence = 1.0;  ///< metres, first stage; a second stage uses a quarter
  int max_iterations = 60;
};

struct RefineResult {
  Eigen::Isometry3d scan_to_world = Eigen::Isometry3d::Identity();
  bool converged = false;
  double fitness = 0.0;  ///< PCL's mean squared distance of the last correspondences
  /// Scan points with a target point within the fine stage's distance (a quarter of
  /// max_correspondence) at the pose found: the pairs the pose rests on.
  std::size_t correspondences = 0;
};

/// \brief Fewest pairs a refined pose must rest on: 20, and a tenth of the scan's registration
/// points. Fewer, and PCL returns the starting pose (no pair at all) or a pose fitted to a few
/// stray points, with nothing to tell it from a registration: refineScanPose refuses it.
std::size_t minRefinePairs(std::size_t scan_points);

/// \brief Which points of a scan (its own frame, z up) registration uses: those with a range in
/// (min_range, max_range) and z > min_z, averaged in `voxel` cells. A car's ground rings travel
/// with the sensor and pull point matching towards zero motion, so a sensor at a known height
/// leaves them out.
struct RegistrationCloudParams {
  float min_range = 0.0f;                                    ///< m (> the carrier's body)
  float max_range = std::numeric_limits<float>::infinity();  ///< m
  float min_z = -std::numeric_limits<float>::infinity();     ///< m, sensor frame
  float voxel = 0.2f;                                        ///< m (> 0)

  /// \brief KITTI's Velodyne HDL-64E, 1.73 m up on a car: 3-40 m, above the ground
  /// (z > -1.3 m), 0.2 m cells.
  static RegistrationCloudParams kittiHdl64();
  /// \brief Every point (no range or height band), 0.2 m cells: a sensor whose mounting is
  /// unknown (a hand-carried scanner).
  static RegistrationCloudParams unbanded() { return {}; }
};

/// \brief \throws std::invalid_argument naming the value: NaN bounds, max_range <= min_range,
/// a voxel that is not finite and > 0
void validateRegistrationCloudParams(const RegistrationCloudParams& params);

/// \brief The registration cloud of a scan (see RegistrationCloudParams), averaged with
/// OccupancyGrid (WorldAligned).
pcl::PointCloud<pcl::PointXYZ>::Ptr registrationCloud(const pcl::PointCloud<pcl::PointXYZ>& scan,
                                                      const RegistrationCloudParams& params);

/// \brief registrationCloud with KITTI's preset and a voxel of `voxel`.
pcl::PointCloud<pcl::PointXYZ>::Ptr registrationCloud(const pcl::PointCloud<pcl::PointXYZ>& velo,
                                                      float voxel = 0.2f);

/// \brief Align `scan` (its own frame) to `target` (world), starting from `initial`.
/// \throws InputError when the pose found rests on fewer than minRefinePairs(scan->size())
/// pairs (the scan overlaps the target too little, or starts too far from it): never a
/// silent starting pose or a pose fitted to a handful of points
RefineResult refineScanPose(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& scan,
                            const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& target,
                            const Eigen::Isometry3d& initial, const RefineParams& params);

/// \brief Translation (metres) and rotation (degrees) of a^-1 * b.
struct PoseError {
  double translation = 0.0;
  double rotation_deg = 0.0;
};
PoseError poseError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

/// \brief `pose` moved by exactly `translation` metres in a random direction and turned by
/// exactly `rotation_deg` about a random axis (through the pose's own origin).
Eigen::Isometry3d perturbPose(const Eigen::Isometry3d& pose, double translation,
                              double rotation_deg, std::mt19937& rng);

}  // namespace metricmap
