#include "metricmap/registration/level_frame.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <pcl/ModelCoefficients.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

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
  UpEstimate best;
  for (int attempt = 0; attempt < 3 && cloud->size() >= kMinInliers; ++attempt) {
    pcl::SACSegmentation<pcl::PointXYZ> seg;
    seg.setOptimizeCoefficients(true);
    seg.setModelType(pcl::SACMODEL_PERPENDICULAR_PLANE);
    seg.setMethodType(pcl::SAC_RANSAC);
    seg.setAxis(Eigen::Vector3f::UnitZ());
    seg.setEpsAngle(static_cast<float>(max_tilt_deg * M_PI / 180.0));
    seg.setDistanceThreshold(distance);
    seg.setMaxIterations(500);
    seg.setInputCloud(cloud);
    pcl::PointIndices inliers;
    pcl::ModelCoefficients c;
    seg.segment(inliers, c);
    if (inliers.indices.size() < kMinInliers || c.values.size() != 4) break;
    Eigen::Vector3d n(c.values[0], c.values[1], c.values[2]);
    double d = c.values[3];
    const double len = n.norm();
    n /= len;
    d /= len;
    if (d < 0.0) {  // orient the normal towards the sensor (the origin above the plane)
      n = -n;
      d = -d;
    }
    if (n.z() >= std::cos(max_tilt_deg * M_PI / 180.0)) {
      best.up = n;
      best.height = d;
      best.inliers = inliers.indices.size();
      return best;
    }
    // A steep plane (a wall's foot): drop it and look again.
    pcl::PointCloud<pcl::PointXYZ> rest;
    std::vector<bool> out(cloud->size(), false);
    for (int i : inliers.indices) out[static_cast<std::size_t>(i)] = true;
    for (std::size_t i = 0; i < cloud->size(); ++i)
      if (!out[i]) rest.push_back((*cloud)[i]);
    *cloud = std::move(rest);
  }
  throw InputError("up estimate: no ground plane (at least " + std::to_string(kMinInliers) +
                   " points below the sensor within " + formatNumber(distance) +
                   " m of a plane tilted less than " + formatNumber(max_tilt_deg) +
                   " deg) in the first scan");
}

Eigen::Isometry3d levelRotation(const Eigen::Vector3d& up) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::Quaterniond::FromTwoVectors(up.normalized(), Eigen::Vector3d::UnitZ())
                   .toRotationMatrix();
  return t;
}

}  // namespace metricmap
