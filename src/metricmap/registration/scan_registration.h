#pragma once
/// \file scan_registration.h
/// \brief Refining a scan's pose against a map with pcl::IterativeClosestPoint or
/// pcl::GeneralizedIterativeClosestPoint; pose perturbation and pose errors for experiments.

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
};

/// \brief The part of a velodyne scan (its own frame, z up) that registration uses: points
/// 3-40 m away and above the ground (z > -1.3 m; the HDL-64E sits 1.73 m up), averaged in
/// `voxel` cells with OccupancyGrid (WorldAligned). The ground's rings travel with the sensor and
/// pull point matching towards zero motion, so they are left out.
pcl::PointCloud<pcl::PointXYZ>::Ptr registrationCloud(const pcl::PointCloud<pcl::PointXYZ>& velo,
                                                      float voxel = 0.2f);

/// \brief Align `scan` (its own frame) to `target` (world), starting from `initial`.
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
