#include "metricmap/mapping/floor_fit.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_perpendicular_plane.h>

#include "metricmap/common/format_number.h"
#include "metricmap/exceptions.h"

namespace metricmap {

FloorPlane fitFloor(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud, double distance_threshold,
                    std::size_t stride) {
  if (stride == 0) throw std::invalid_argument("floor fit: stride must be at least 1, got 0");
  if (!std::isfinite(distance_threshold) || !(distance_threshold > 0.0)) {
    throw std::invalid_argument("floor fit: distance threshold must be a finite number > 0, got " +
                                formatNumber(distance_threshold));
  }
  auto sample = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  std::size_t k = 0;
  for (const auto& p : camera_cloud) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && k++ % stride == 0) {
      sample->push_back(p);
    }
  }
  if (sample->size() < 100) throw InputError("floor fit: fewer than 100 valid points");
  // What pcl::SACSegmentation (RANSAC, SACMODEL_PERPENDICULAR_PLANE, optimised coefficients)
  // does, on pcl_sample_consensus alone: the segmentation module costs ~0.1 s of start-up.
  auto model = std::make_shared<pcl::SampleConsensusModelPerpendicularPlane<pcl::PointXYZ>>(
      sample, /*random=*/false);
  model->setAxis(Eigen::Vector3f(0.0f, -1.0f, 0.0f));
  model->setEpsAngle(70.0 * M_PI / 180.0);
  pcl::RandomSampleConsensus<pcl::PointXYZ> sac(model, distance_threshold);
  sac.setMaxIterations(500);
  sac.setProbability(0.99);
  pcl::Indices inliers;
  if (!sac.computeModel(0)) throw InputError("floor fit: no plane found");
  sac.getInliers(inliers);
  Eigen::VectorXf coeff(4), refined(4);
  sac.getModelCoefficients(coeff);
  model->optimizeModelCoefficients(inliers, coeff, refined);
  model->selectWithinDistance(refined, distance_threshold, inliers);
  if (inliers.size() < 100 || refined.size() != 4) {
    throw InputError("floor fit: no plane found");
  }
  const std::vector<float> values(refined.data(), refined.data() + 4);
  FloorPlane f;
  const Eigen::Vector3d n(values[0], values[1], values[2]);
  const double len = n.norm();
  f.normal = n / len;
  f.d = values[3] / len;
  if (f.d < 0) {
    f.normal = -f.normal;
    f.d = -f.d;
  }
  f.inliers = inliers.size();
  return f;
}

}  // namespace metricmap
