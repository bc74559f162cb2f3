#include "metricmap/detail/voxel_key.h"

#include <string>

#include "metricmap/exceptions.h"

namespace metricmap {

void throwVoxelRange(const Eigen::Vector3d& p) {
  throw CapacityError("voxel index of point (" + std::to_string(p.x()) + ", " +
                      std::to_string(p.y()) + ", " + std::to_string(p.z()) +
                      ") outside +-2^20 cells");
}

}  // namespace metricmap
