#include "metricmap/registration/voxel_hash_map.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

// Squared distance from p to a point, as Eigen's squaredNorm() of the difference gives it.
inline double squaredDistance(double x, double y, double z, const Eigen::Vector3d& p) {
  const double dx = x - p.x(), dy = y - p.y(), dz = z - p.z();
  return (dx * dx + dy * dy) + dz * dz;
}

// Smallest squared distance from p to the n points of a voxel block (x, y, z rows `stride`
// apart), two points at a time where SSE2 is there (the same operations, lane by lane).
double nearestInVoxel(const double* x, std::size_t stride, int n, const Eigen::Vector3d& p) {
  const double* y = x + stride;
  const double* z = y + stride;
  double best = std::numeric_limits<double>::infinity();
  int j = 0;
#if defined(__SSE2__)
  const __m128d px = _mm_set1_pd(p.x()), py = _mm_set1_pd(p.y()), pz = _mm_set1_pd(p.z());
  __m128d lowest = _mm_set1_pd(best);
  for (; j + 2 <= n; j += 2) {
    const __m128d dx = _mm_sub_pd(_mm_loadu_pd(x + j), px);
    const __m128d dy = _mm_sub_pd(_mm_loadu_pd(y + j), py);
    const __m128d dz = _mm_sub_pd(_mm_loadu_pd(z + j), pz);
    lowest = _mm_min_pd(
        lowest, _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz)));
  }
  best = std::min(_mm_cvtsd_f64(lowest), _mm_cvtsd_f64(_mm_unpackhi_pd(lowest, lowest)));
#endif
  for (; j < n; ++j) best = std::min(best, squaredDistance(x[j], y[j], z[j], p));
  return best;
}

// The first of the n points of a voxel block at squared distance d2 from p.
int firstAt(const double* x, std::size_t stride, int n, const Eigen::Vector3d& p, double d2) {
  for (int k = 0; k < n; ++k) {
    if (squaredDistance(x[k], x[k + stride], x[k + 2 * stride], p) == d2) return k;
  }
  return 0;  // not reached: d2 is one of the points' distances
}

}  // namespace

VoxelHashMap::VoxelHashMap(double voxel, int max_points)
    : voxel_(voxel), inv_voxel_(1.0 / voxel), stride_(static_cast<std::size_t>(max_points)) {
  if (!(std::isfinite(voxel) && voxel > 0.0)) {
    throw std::invalid_argument("map voxel size must be a finite number > 0, got " +
                                std::to_string(voxel));
  }
  if (max_points < 1 || max_points > kMaxPointsPerVoxel) {
    throw std::invalid_argument("points per voxel must be in 1.." +
                                std::to_string(kMaxPointsPerVoxel) + ", got " +
                                std::to_string(max_points));
  }
  rebuildTable(1024);
}

void VoxelHashMap::clear() {
  keys_.clear();
  counts_.clear();
  coords_.clear();
  held_ = 0;
  rebuildTable(1024);
}

void VoxelHashMap::rebuildTable(std::size_t capacity) {
  table_.assign(capacity, Slot{0, -1});
  mask_ = capacity - 1;
  shift_ = fibonacciShift(capacity);
  for (std::size_t v = 0; v < keys_.size(); ++v) place(keys_[v], static_cast<std::int32_t>(v));
}

void VoxelHashMap::place(std::uint64_t key, std::int32_t voxel) {
  std::size_t i = fibonacciSlot(key, shift_);
  while (table_[i].voxel >= 0) i = (i + 1) & mask_;
  table_[i] = Slot{key, voxel};
}

std::int32_t VoxelHashMap::find(std::uint64_t key) const {
  for (std::size_t i = fibonacciSlot(key, shift_);; i = (i + 1) & mask_) {
    const Slot& s = table_[i];
    if (s.voxel < 0 || s.key == key) return s.voxel;
  }
}

std::int32_t VoxelHashMap::findOrAdd(std::uint64_t key) {
  const std::int32_t found = find(key);
  if (found >= 0) return found;
  if (keys_.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw CapacityError("local map: more than 2^31 voxels");
  }
  // Everything that allocates first, so that running out of memory leaves the map as it was.
  const std::size_t n = keys_.size() + 1;
  if (n > keys_.capacity()) keys_.reserve(2 * n);  // geometric growth, as push_back's
  if (n > counts_.capacity()) counts_.reserve(2 * n);
  coords_.resize(n * 3 * stride_);
  if (2 * n > table_.size()) rebuildTable(2 * table_.size());
  const auto v = static_cast<std::int32_t>(keys_.size());
  keys_.push_back(key);
  counts_.push_back(0);
  place(key, v);
  return v;
}

void VoxelHashMap::add(const std::vector<Eigen::Vector3d>& points) {
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Array3i c = voxelOf(p, inv_voxel_);
    const std::int32_t v = findOrAdd(packVoxelKey(c.x(), c.y(), c.z()));
    std::int32_t& n = counts_[static_cast<std::size_t>(v)];
    if (static_cast<std::size_t>(n) >= stride_) continue;
    double* x = block(v) + n;
    x[0] = p.x();
    x[stride_] = p.y();
    x[2 * stride_] = p.z();
    ++n;
    ++held_;
  }
}

void VoxelHashMap::removeFar(const Eigen::Vector3d& origin, double radius) {
  const double r2 = radius * radius;
  // Keep the survivors in their order, packed to the front.
  std::size_t out = 0;
  for (std::size_t v = 0; v < keys_.size(); ++v) {
    const auto vi = static_cast<std::int32_t>(v);
    if ((voxelPoint(vi, 0) - origin).squaredNorm() > r2) {
      held_ -= static_cast<std::size_t>(counts_[v]);
      continue;
    }
    if (out != v) {
      keys_[out] = keys_[v];
      counts_[out] = counts_[v];
      std::copy_n(block(vi), 3 * stride_, block(static_cast<std::int32_t>(out)));
    }
    ++out;
  }
  if (out == keys_.size()) return;
  keys_.resize(out);
  counts_.resize(out);
  coords_.resize(out * 3 * stride_);
  rebuildTable(table_.size());
}

bool VoxelHashMap::nearestCached(const Eigen::Vector3d& p, double max_distance, Neighbourhood& hood,
                                 Eigen::Vector3d& q, std::int32_t* voxel) const {
  const Eigen::Array3d s = p.array() * inv_voxel_;
  const Eigen::Array3i c = voxelOfScaled(s, p);
  const std::uint64_t key = packVoxelKey(c.x(), c.y(), c.z());
  if (key != hood.key) {
    hood.key = key;
    hood.center = c;
    hood.looked_up = 0;
  }
  auto cellAt = [&](int i) {
    if ((hood.looked_up >> i & 1u) == 0) {
      hood.cells[i] =
          find(packVoxelKey(hood.center.x() + i / 9 - 1, hood.center.y() + i / 3 % 3 - 1,
                            hood.center.z() + i % 3 - 1));
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
  std::int32_t best_voxel = -1;
  int best_k = 0;
  // A margin for rounding: skip only voxels clearly farther than the best so far. The faces'
  // distances carry the rounding of p / voxel, which grows with the coordinates.
  const double slack = 1e-12 + 8.0 * voxel_ * voxel_ * (s.abs().maxCoeff() + 1.0) *
                                   std::numeric_limits<double>::epsilon();
  auto farther = [&](double d2) { return d2 > best * (1.0 + 1e-9) + slack; };
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
        const std::int32_t v = cellAt(i);
        if (v < 0) continue;
        const int n = counts_[static_cast<std::size_t>(v)];
        const double d2 = nearestInVoxel(block(v), stride_, n, p);
        if (d2 < best || (d2 == best && best_voxel >= 0 && i < best_cell)) {
          best = d2;
          best_cell = i;
          best_voxel = v;
          best_k = firstAt(block(v), stride_, n, p, d2);
        }
      }
    }
  }
  if (best_voxel < 0) return false;
  q = voxelPoint(best_voxel, best_k);
  if (voxel != nullptr) *voxel = best_voxel;
  return true;
}

bool VoxelHashMap::nearest(const Eigen::Vector3d& p, double max_distance,
                           Eigen::Vector3d& q) const {
  Neighbourhood hood;
  return nearestCached(p, max_distance, hood, q);
}

std::int32_t VoxelHashMap::voxelOfPoint(const Eigen::Vector3d& p) const {
  const Eigen::Array3i c = voxelOf(p, inv_voxel_);
  return find(packVoxelKey(c.x(), c.y(), c.z()));
}

std::size_t VoxelHashMap::bytes() const {
  return keys_.capacity() * sizeof(std::uint64_t) + counts_.capacity() * sizeof(std::int32_t) +
         coords_.capacity() * sizeof(double) + table_.capacity() * sizeof(Slot);
}

std::vector<Eigen::Vector3d> VoxelHashMap::cloud() const {
  std::vector<Eigen::Vector3d> out;
  out.reserve(held_);
  for (std::size_t v = 0; v < keys_.size(); ++v) {
    const auto vi = static_cast<std::int32_t>(v);
    for (int k = 0; k < counts_[v]; ++k) out.push_back(voxelPoint(vi, k));
  }
  return out;
}

}  // namespace metricmap
