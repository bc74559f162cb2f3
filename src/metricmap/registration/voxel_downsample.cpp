#include "metricmap/registration/voxel_downsample.h"

#include <stdexcept>
#include <unordered_set>

#include "metricmap/registration/voxel_key.h"

namespace metricmap {

Points3d voxelDownsample(const Points3d& points, double voxel, std::vector<int>* kept) {
  if (!(std::isfinite(voxel) && voxel > 0.0)) {
    throw std::invalid_argument("voxel size must be a finite number > 0, got " +
                                std::to_string(voxel));
  }
  const double inv = 1.0 / voxel;
  std::unordered_set<std::uint64_t, VoxelKeyHash> seen;
  seen.reserve(points.size() / 4 + 16);
  Points3d out;
  out.reserve(points.size() / 4 + 16);
  if (kept) kept->clear();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Array3i c = voxelOf(points[i], inv);
    if (seen.insert(packVoxel(c.x(), c.y(), c.z())).second) {
      out.push_back(points[i]);
      if (kept) kept->push_back(static_cast<int>(i));
    }
  }
  return out;
}

}  // namespace metricmap
