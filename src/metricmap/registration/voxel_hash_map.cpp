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

int VoxelHashMap::neighbours(const Eigen::Vector3d& p, const Cell* out[27],
                             Offset offsets[27]) const {
  const Eigen::Array3i c = voxelOf(p, inv_voxel_);
  int n = 0;
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dz = -1; dz <= 1; ++dz) {
        const auto it = map_.find(packVoxel(c.x() + dx, c.y() + dy, c.z() + dz));
        if (it == map_.end()) continue;
        offsets[n] = {{static_cast<std::int8_t>(dx), static_cast<std::int8_t>(dy),
                       static_cast<std::int8_t>(dz)}};
        out[n++] = &it->second;
      }
    }
  }
  return n;
}

bool VoxelHashMap::nearestIn(const Cell* const* cells, const Offset* offsets, int n,
                             const Eigen::Vector3d& p, double max_distance,
                             Eigen::Vector3d& q) const {
  // Squared distance from p to the faces of its voxel, below and above, per axis.
  const Eigen::Array3d s = p.array() * inv_voxel_;
  const Eigen::Array3d f = s - s.floor();
  const Eigen::Array3d below = (f * voxel_).square(), above = ((1.0 - f) * voxel_).square();
  double best = max_distance * max_distance;
  int best_cell = n;  // the answer of a scan in the given order: ties go to the earlier cell
  bool found = false;
  auto visit = [&](int i) {
    for (const Eigen::Vector3d& m : *cells[i]) {
      const double d2 = (m - p).squaredNorm();
      if (d2 < best || (d2 == best && found && i < best_cell)) {
        best = d2;
        best_cell = i;
        q = m;
        found = true;
      }
    }
  };
  // The query's own voxel first: it usually holds the answer, and then most others are skipped.
  int own = -1;
  for (int i = 0; i < n; ++i) {
    if (offsets[i].d[0] == 0 && offsets[i].d[1] == 0 && offsets[i].d[2] == 0) own = i;
  }
  if (own >= 0) visit(own);
  for (int i = 0; i < n; ++i) {
    if (i == own) continue;
    double box = 0.0;
    for (int a = 0; a < 3; ++a) {
      box += offsets[i].d[a] < 0 ? below[a] : (offsets[i].d[a] > 0 ? above[a] : 0.0);
    }
    // A margin for rounding: skip only cells clearly farther than the best so far.
    if (box > best * (1.0 + 1e-9) + 1e-12) continue;
    visit(i);
  }
  return found;
}

bool VoxelHashMap::nearest(const Eigen::Vector3d& p, double max_distance,
                           Eigen::Vector3d& q) const {
  const Cell* cells[27];
  Offset offsets[27];
  const int n = neighbours(p, cells, offsets);
  return nearestIn(cells, offsets, n, p, max_distance, q);
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
