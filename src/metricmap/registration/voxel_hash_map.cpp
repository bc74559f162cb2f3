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
  const Eigen::Array3d cell = s.floor();
  const Eigen::Array3i c = voxelOf(p, inv_voxel_);
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
  // Squared distance from p to the faces of its voxel, below and above, per axis.
  const Eigen::Array3d f = s - cell;
  const Eigen::Array3d below = (f * voxel_).square(), above = ((1.0 - f) * voxel_).square();
  double best = max_distance * max_distance;
  int best_cell = 27;
  bool found = false;
  auto visit = [&](int i) {
    const Cell* points = cellAt(i);
    if (points == nullptr) return;
    for (const Eigen::Vector3d& m : *points) {
      const double d2 = (m - p).squaredNorm();
      if (d2 < best || (d2 == best && found && i < best_cell)) {
        best = d2;
        best_cell = i;
        q = m;
        found = true;
      }
    }
  };
  constexpr int kOwn = 13;  // dx = dy = dz = 0: it usually holds the answer
  visit(kOwn);
  for (int i = 0; i < 27; ++i) {
    if (i == kOwn) continue;
    const int d[3] = {i / 9 - 1, i / 3 % 3 - 1, i % 3 - 1};
    double box = 0.0;
    for (int a = 0; a < 3; ++a) box += d[a] < 0 ? below[a] : (d[a] > 0 ? above[a] : 0.0);
    // A margin for rounding: skip only voxels clearly farther than the best so far.
    if (box > best * (1.0 + 1e-9) + 1e-12) continue;
    visit(i);
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
