#include "metricmap/localization/place_descriptor_3d.h"

#include <algorithm>
#include <cmath>

namespace metricmap {

ScanContext placeDescriptor(std::vector<Eigen::Vector3f> relative, const PlaceDescriptorParams& p) {
  for (Eigen::Vector3f& q : relative) {
    const double r = std::hypot(double(q.x()), double(q.y()));
    q.z() = static_cast<float>(std::min(double(q.z()), p.clip_height + p.clip_slope * r));
  }
  return makeScanContext(relative, p.shape);
}

ScanContext scanDescriptor(const std::vector<Eigen::Vector3d>& scan, const ScanGround& ground,
                           const PlaceDescriptorParams& p) {
  std::vector<Eigen::Vector3f> relative;
  relative.reserve(scan.size());
  for (const Eigen::Vector3d& s : scan) {
    Eigen::Vector3d q = ground.level * s;
    q.z() += ground.height;
    relative.push_back(q.cast<float>());
  }
  return placeDescriptor(std::move(relative), p);
}

}  // namespace metricmap
