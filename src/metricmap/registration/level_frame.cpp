#include "metricmap/registration/level_frame.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_perpendicular_plane.h>

#include "metricmap/common/format_number.h"
#include "metricmap/exceptions.h"

namespace metricmap {

UpEstimate estimateUp(const std::vector<Eigen::Vector3d>& points, double distance,
                      double max_tilt_deg) {
  if (!(std::isfinite(distance) && distance > 0.0)) {
    throw std::invalid_argument("up estimate: distance must be a finite number > 0, got " +
                                formatNumber(distance));
  }
  if (!(std::isfinite(max_tilt_deg) && max_tilt_deg > 0.0 && max_tilt_deg < 90.0)) {
    throw std::invalid_argument("up estimate: max_tilt_deg must be in (0, 90), got " +
                                formatNumber(max_tilt_deg));
  }
  // Only points below the sensor can be its ground.
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const Eigen::Vector3d& p : points) {
    if (p.allFinite() && p.z() < 0.0)
      cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                     static_cast<float>(p.z())));
  }
  constexpr std::size_t kMinInliers = 50;
  const std::string none = "up estimate: no ground plane (at least " + std::to_string(kMinInliers) +
                           " points below the sensor within " + formatNumber(distance) +
                           " m of a plane tilted less than " + formatNumber(max_tilt_deg) +
                           " deg) in the first scan";
  if (cloud->size() < kMinInliers) throw InputError(none);
  // RANSAC over planes within the tilt of the sensor's z (fixed seed), then least squares over
  // the inliers and the inliers of the refined plane.
  auto model = std::make_shared<pcl::SampleConsensusModelPerpendicularPlane<pcl::PointXYZ>>(
      cloud, /*random=*/false);
  model->setAxis(Eigen::Vector3f::UnitZ());
  model->setEpsAngle(max_tilt_deg * M_PI / 180.0);
  pcl::RandomSampleConsensus<pcl::PointXYZ> sac(model, distance);
  sac.setMaxIterations(500);
  sac.setProbability(0.99);
  if (!sac.computeModel(0)) throw InputError(none);
  pcl::Indices inliers;
  sac.getInliers(inliers);
  Eigen::VectorXf coeff(4), refined(4);
  sac.getModelCoefficients(coeff);
  model->optimizeModelCoefficients(inliers, coeff, refined);
  model->selectWithinDistance(refined, distance, inliers);
  if (inliers.size() < kMinInliers || refined.size() != 4) throw InputError(none);
  Eigen::Vector3d n(refined[0], refined[1], refined[2]);
  double d = refined[3];
  const double len = n.norm();
  n /= len;
  d /= len;
  if (d < 0.0) {  // orient the normal towards the sensor (the origin above the plane)
    n = -n;
    d = -d;
  }
  if (n.z() < std::cos(max_tilt_deg * M_PI / 180.0)) throw InputError(none);
  UpEstimate best;
  best.up = n;
  best.height = d;
  best.inliers = inliers.size();
  return best;
}

Eigen::Isometry3d levelRotation(const Eigen::Vector3d& up) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::Quaterniond::FromTwoVectors(up.normalized(), Eigen::Vector3d::UnitZ())
                   .toRotationMatrix();
  return t;
}

}  // namespace metricmap
