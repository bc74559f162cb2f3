#include "metricmap/registration/scan_registration.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <pcl/registration/gicp.h>
#include <pcl/registration/icp.h>

#include "metricmap/common/format_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"

namespace metricmap {
namespace {

Eigen::Vector3d randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::Vector3d v;
  do {
    v = Eigen::Vector3d(g(rng), g(rng), g(rng));
  } while (v.norm() < 1e-9);
  return v.normalized();
}

template <typename Registration>
RefineResult run(Registration& reg, const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& scan,
                 const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& target,
                 const Eigen::Isometry3d& initial, const RefineParams& p) {
  reg.setInputSource(scan);
  reg.setInputTarget(target);
  reg.setMaximumIterations(p.max_iterations);
  reg.setTransformationEpsilon(1e-10);
  reg.setEuclideanFitnessEpsilon(1e-8);
  pcl::PointCloud<pcl::PointXYZ> aligned;
  Eigen::Matrix4f guess = initial.matrix().cast<float>();
  RefineResult r;
  // Coarse then fine: the first stage pulls in from up to max_correspondence, the second
  // refines with a quarter of it so that far outliers no longer drag the result.
  for (double dist : {p.max_correspondence, p.max_correspondence / 4}) {
    reg.setMaxCorrespondenceDistance(dist);
    reg.align(aligned, guess);
    guess = reg.getFinalTransformation();
    r.converged = reg.hasConverged();
    r.fitness = reg.getFitnessScore(dist);
  }
  r.scan_to_world.matrix() = guess.cast<double>();
  // The pairs of the pose found: `aligned` is the scan at it; the target's tree is built.
  const double fine = p.max_correspondence / 4;
  const auto tree = reg.getSearchMethodTarget();
  pcl::Indices index(1);
  std::vector<float> sq(1);
  for (const pcl::PointXYZ& q : aligned) {
    if (tree->nearestKSearch(q, 1, index, sq) > 0 && sq[0] <= fine * fine) ++r.correspondences;
  }
  const std::size_t need = minRefinePairs(scan->size());
  if (r.correspondences < need) {
    throw InputError("registration paired " + std::to_string(r.correspondences) +
                     " of the scan's " + std::to_string(scan->size()) +
                     " registration points with the target within " + formatNumber(fine) +
                     " m, at least " + std::to_string(need) +
                     " needed (20, and a tenth of the points): the pose cannot be trusted (the "
                     "scan overlaps the target too little, or its initial pose is too far off)");
  }
  return r;
}

}  // namespace

std::size_t minRefinePairs(std::size_t scan_points) {
  constexpr std::size_t kMinPairs = 20;
  return std::max(kMinPairs, (scan_points + 9) / 10);
}

RefineMethod parseRefineMethod(const std::string& name) {
  if (name == "icp") return RefineMethod::Icp;
  if (name == "gicp") return RefineMethod::Gicp;
  throw std::invalid_argument("refine method must be icp or gicp, got '" + name + "'");
}

RegistrationCloudParams RegistrationCloudParams::kittiHdl64() {
  RegistrationCloudParams p;
  p.min_range = 3.0f;
  p.max_range = 40.0f;
  p.min_z = -1.3f;
  return p;
}

void validateRegistrationCloudParams(const RegistrationCloudParams& p) {
  if (std::isnan(p.min_range) || std::isnan(p.max_range) || std::isnan(p.min_z) ||
      !(p.max_range > p.min_range))
    throw std::invalid_argument(
        "registration cloud: the range band must be numbers with "
        "max_range > min_range");
  if (!std::isfinite(p.voxel) || !(p.voxel > 0.0f))
    throw std::invalid_argument("registration voxel must be a finite number > 0");
}

pcl::PointCloud<pcl::PointXYZ>::Ptr registrationCloud(const pcl::PointCloud<pcl::PointXYZ>& velo,
                                                      float voxel) {
  RegistrationCloudParams p = RegistrationCloudParams::kittiHdl64();
  p.voxel = voxel;
  return registrationCloud(velo, p);
}

pcl::PointCloud<pcl::PointXYZ>::Ptr registrationCloud(const pcl::PointCloud<pcl::PointXYZ>& scan,
                                                      const RegistrationCloudParams& params) {
  validateRegistrationCloudParams(params);
  auto structure = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : scan) {
    const float r = p.getVector3fMap().norm();
    if (r > params.min_range && r < params.max_range && p.z > params.min_z) structure->push_back(p);
  }
  structure->width = static_cast<std::uint32_t>(structure->size());
  structure->height = 1;
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setOrigin(GridOrigin::WorldAligned);
  grid.setCellSize(params.voxel);
  grid.setInputCloud(structure);
  auto out = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  grid.filter(*out);
  return out;
}

RefineResult refineScanPose(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& scan,
                            const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& target,
                            const Eigen::Isometry3d& initial, const RefineParams& params) {
  if (params.method == RefineMethod::Gicp) {
    pcl::GeneralizedIterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> gicp;
    return run(gicp, scan, target, initial, params);
  }
  pcl::IterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> icp;
  return run(icp, scan, target, initial, params);
}

PoseError poseError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  // Full inverse: KITTI's Tr makes these matrices orthonormal only to ~1e-7.
  const Eigen::Matrix4d d = a.matrix().inverse() * b.matrix();
  PoseError e;
  e.translation = d.block<3, 1>(0, 3).norm();
  const double c = std::max(-1.0, std::min(1.0, (d.block<3, 3>(0, 0).trace() - 1.0) / 2.0));
  e.rotation_deg = std::acos(c) * 180.0 / M_PI;
  return e;
}

Eigen::Isometry3d perturbPose(const Eigen::Isometry3d& pose, double translation,
                              double rotation_deg, std::mt19937& rng) {
  Eigen::Isometry3d delta = Eigen::Isometry3d::Identity();
  delta.linear() =
      Eigen::AngleAxisd(rotation_deg * M_PI / 180.0, randomUnit(rng)).toRotationMatrix();
  delta.translation() = translation * randomUnit(rng);
  return pose * delta;
}

}  // namespace metricmap
