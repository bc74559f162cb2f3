#include "metricmap/height/floor_fit.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

namespace metricmap {

FloorPlane fitFloor(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud, double distance_threshold,
                    std::size_t stride) {
  if (stride == 0) throw std::invalid_argument("floor fit: stride must be at least 1, got 0");
  if (!std::isfinite(distance_threshold) || !(distance_threshold > 0.0)) {
    throw std::invalid_argument("floor fit: distance threshold must be a finite number > 0, got " +
                                std::to_string(distance_threshold));
  }
  auto sample = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  std::size_t k = 0;
  for (const auto& p : camera_cloud) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && k++ % stride == 0) {
      sample->push_back(p);
    }
  }
  if (sample->size() < 100) throw std::runtime_error("floor fit: fewer than 100 valid points");
  pcl::SACSegmentation<pcl::PointXYZ> sac;
  sac.setModelType(pcl::SACMODEL_PERPENDICULAR_PLANE);
  sac.setMethodType(pcl::SAC_RANSAC);
  sac.setAxis(Eigen::Vector3f(0.0f, -1.0f, 0.0f));
  sac.setEpsAngle(70.0 * M_PI / 180.0);
  sac.setDistanceThreshold(distance_threshold);
  sac.setMaxIterations(500);
  sac.setInputCloud(sample);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coeffs;
  sac.segment(inliers, coeffs);
  if (inliers.indices.size() < 100 || coeffs.values.size() != 4) {
    throw std::runtime_error("floor fit: no plane found");
  }
  FloorPlane f;
  const Eigen::Vector3d n(coeffs.values[0], coeffs.values[1], coeffs.values[2]);
  const double len = n.norm();
  f.normal = n / len;
  f.d = coeffs.values[3] / len;
  if (f.d < 0) {
    f.normal = -f.normal;
    f.d = -f.d;
  }
  f.inliers = inliers.indices.size();
  return f;
}

}  // namespace metricmap
