#include "metricmap/detail/voxel_key.h"

#include <sstream>

#include "metricmap/exceptions.h"

namespace metricmap {

void throwVoxelRange(const Eigen::Vector3d& p) {
  std::ostringstream msg;
  msg << "point (" << p.x() << ", " << p.y() << ", " << p.z()
      << ") is outside the voxel key space (+-2^20 cells from the origin)";
  throw CapacityError(msg.str());
}

}  // namespace metricmap
