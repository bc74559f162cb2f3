#include "metricmap/registration/voxel_hash_map.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace metricmap {

VoxelHashMap::VoxelHashMap(double voxel, int max_points)
    : voxel_(voxel), inv_voxel_(1.0 / voxel), max_points_(max_points) {
  if (!(std::isfinite(voxel) && voxel > 0.0)) {
    throw std::invalid_argument("map voxel size must be a finite number > 0, got " +
                                std::to_string(voxel));
  }
  if (max_points < 1) {
    throw std::invalid_argument("points per voxel must be >= 1, got " + std::to_string(max_points));
  }
}

void VoxelHashMap::add(const std::vector<Eigen::Vector3d>& points) {
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Array3i c = voxelOf(p, inv_voxel_);
    auto& cell = map_[packVoxel(c.x(), c.y(), c.z())];
    if (cell.size() >= static_cast<std::size_t>(max_points_)) continue;
    if (cell.empty()) cell.reserve(static_cast<std::size_t>(max_points_));
    cell.push_back(p);
    ++points_;
  }
}

void VoxelHashMap::removeFar(const Eigen::Vector3d& origin, double radius) {
  const double r2 = radius * radius;
  for (auto it = map_.begin(); it != map_.end();) {
    if ((it->second.front() - origin).squaredNorm() > r2) {
      points_ -= it->second.size();
      it = map_.erase(it);
    } else {
      ++it;
    }
  }
}

bool VoxelHashMap::nearestCached(const Eigen::Vector3d& p, double max_distance, Neighbourhood& hood,
                                 Eigen::Vector3d& q) const {
  const Eigen::Array3d s = p.array() * inv_voxel_;
  const Eigen::Array3i c = voxelOfScaled(s, p);
  const std::uint64_t key = packVoxel(c.x(), c.y(), c.z());
  if (key != hood.key) {
    hood.key = key;
    hood.center = c;
    hood.looked_up = 0;
  }
  auto cellAt = [&](int i) {
    if ((hood.looked_up >> i & 1u) == 0) {
      const auto it =
          map_.find(packVoxel(hood.center.x() + i / 9 - 1, hood.center.y() + i / 3 % 3 - 1,
                              hood.center.z() + i % 3 - 1));
      hood.cells[i] = it == map_.end() ? nullptr : &it->second;
      hood.looked_up |= 1u << i;
    }
    return hood.cells[i];
  };
  // Squared distance from p to the neighbour voxels' boxes, per axis and offset -1, 0, +1
  // (index 0, 1, 2): a neighbour's box distance is the sum over its three offsets.
  const Eigen::Array3d f = s - c.cast<double>();
  const Eigen::Array3d below = (f * voxel_).square(), above = ((1.0 - f) * voxel_).square();
  const double box[3][3] = {
      {below[0], 0.0, above[0]}, {below[1], 0.0, above[1]}, {below[2], 0.0, above[2]}};
  double best = max_distance * max_distance;
  int best_cell = 27;
  bool found = false;
  // A margin for rounding: skip only voxels clearly farther than the best so far.
  auto farther = [&](double d2) { return d2 > best * (1.0 + 1e-9) + 1e-12; };
  // Own voxel first (it usually holds the answer), then outwards, one axis at a time, so that
  // a slab of 9 or a row of 3 voxels whose nearest face is already too far is skipped whole.
  // Ties go to the lower index, as a scan of the 27 voxels in index order would give.
  constexpr int kOrder[3] = {1, 0, 2};
  for (const int x : kOrder) {
    if (farther(box[0][x])) continue;
    for (const int y : kOrder) {
      const double bxy = box[0][x] + box[1][y];
      if (farther(bxy)) continue;
      for (const int z : kOrder) {
        if (farther(bxy + box[2][z])) continue;
        const int i = 9 * x + 3 * y + z;
        const Cell* points = cellAt(i);
        if (points == nullptr) continue;
        for (const Eigen::Vector3d& m : *points) {
          const double d2 = (m - p).squaredNorm();
          if (d2 < best || (d2 == best && found && i < best_cell)) {
            best = d2;
            best_cell = i;
            q = m;
            found = true;
          }
        }
      }
    }
  }
  return found;
}

bool VoxelHashMap::nearest(const Eigen::Vector3d& p, double max_distance,
                           Eigen::Vector3d& q) const {
  Neighbourhood hood;
  return nearestCached(p, max_distance, hood, q);
}

const std::vector<Eigen::Vector3d>* VoxelHashMap::voxelPoints(const Eigen::Vector3d& p) const {
  const Eigen::Array3i c = voxelOf(p, inv_voxel_);
  const auto it = map_.find(packVoxel(c.x(), c.y(), c.z()));
  return it == map_.end() ? nullptr : &it->second;
}

std::size_t VoxelHashMap::bytes() const {
  // Each voxel: a hash node (key, vector header, next pointer) plus a bucket pointer, and its
  // reserved point storage.
  const std::size_t node =
      sizeof(std::uint64_t) + sizeof(std::vector<Eigen::Vector3d>) + sizeof(void*) + sizeof(void*);
  return map_.size() * (node + static_cast<std::size_t>(max_points_) * sizeof(Eigen::Vector3d));
}

std::vector<Eigen::Vector3d> VoxelHashMap::cloud() const {
  std::vector<Eigen::Vector3d> out;
  out.reserve(points_);
  for (const auto& kv : map_) out.insert(out.end(), kv.second.begin(), kv.second.end());
  return out;
}

}  // namespace metricmap
