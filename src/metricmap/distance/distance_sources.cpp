#include "metricmap/distance/distance_sources.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/detail/voxel_key.h"
#include "metricmap/exceptions.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/octomap_file_check.h"

namespace metricmap {
namespace {

/// Price the field of a box before its states are allocated.
void priceBox(const std::array<std::size_t, 3>& shape, int dims, double resolution,
              const DistanceFieldParams& params) {
  validateDistanceFieldParams(params);
  std::ostringstream what;
  what << "distance field of " << shape[0] << " x " << shape[1];
  if (dims == 3) what << " x " << shape[2];
  what << " voxels at " << resolution << " m";
  // shapes come from input files: the product may overflow
  std::uint64_t xy = 0, n = 0;
  if (__builtin_mul_overflow(std::uint64_t{shape[0]}, std::uint64_t{shape[1]}, &xy) ||
      __builtin_mul_overflow(xy, std::uint64_t{shape[2]}, &n))
    throw CapacityError(what.str() + ": too many voxels");
  checkMemory(n, distanceFieldBytesPerVoxel(params), what.str());
}

}  // namespace

OccupancyBox occupancyBoxOf(const LogOddsMap& map, const DistanceFieldParams& params,
                            const std::optional<KeyBox>& box) {
  KeyBox kb;
  if (box) {
    kb = *box;
  } else {
    VoxelKey lo, hi;
    if (!map.keyBounds(lo, hi)) throw std::invalid_argument("distance field: the map is empty");
    kb.min_key = {lo.x, lo.y, lo.z};
    kb.shape = {static_cast<std::size_t>(hi.x - lo.x + 1),
                static_cast<std::size_t>(hi.y - lo.y + 1),
                static_cast<std::size_t>(hi.z - lo.z + 1)};
  }
  if (kb.shape[0] == 0 || kb.shape[1] == 0 || kb.shape[2] == 0)
    throw std::invalid_argument("distance field: empty box");
  priceBox(kb.shape, 3, map.resolution(), params);
  OccupancyBox out;
  out.dimensions = 3;
  out.shape = kb.shape;
  out.resolution = map.resolution();
  out.min_key = kb.min_key;
  out.origin = map.centerOf(VoxelKey{kb.min_key[0], kb.min_key[1], kb.min_key[2]});
  out.state.assign(out.voxels(), kVoxelUnknown);
  const auto& s = out.shape;
  map.forEachBlock([&](std::uint64_t block_key, const std::uint64_t* known, const float* lo) {
    const VoxelKey b = unpackVoxelKey(block_key);
    const std::int64_t bx = b.x * detail::kBlockEdge - kb.min_key[0];
    const std::int64_t by = b.y * detail::kBlockEdge - kb.min_key[1];
    const std::int64_t bz = b.z * detail::kBlockEdge - kb.min_key[2];
    if (bx + 8 <= 0 || by + 8 <= 0 || bz + 8 <= 0 || bx >= static_cast<std::int64_t>(s[0]) ||
        by >= static_cast<std::int64_t>(s[1]) || bz >= static_cast<std::int64_t>(s[2]))
      return;
    for (int w = 0; w < detail::kBlockWords; ++w) {
      for (std::uint64_t bits = known[w]; bits != 0; bits &= bits - 1) {
        const int v = w * 64 + __builtin_ctzll(bits);
        const std::int64_t x = bx + (v & 7), y = by + ((v >> 3) & 7), z = bz + (v >> 6);
        if (x < 0 || y < 0 || z < 0 || x >= static_cast<std::int64_t>(s[0]) ||
            y >= static_cast<std::int64_t>(s[1]) || z >= static_cast<std::int64_t>(s[2]))
          continue;
        out.state[(static_cast<std::size_t>(x) * s[1] + static_cast<std::size_t>(y)) * s[2] +
                  static_cast<std::size_t>(z)] =
            map.isOccupied(lo[v]) ? kVoxelOccupied : kVoxelFree;
      }
    }
  });
  return out;
}

OccupancyBox occupancyBoxOf(const Map2D& map, const DistanceFieldParams& params) {
  if (map.width <= 0 || map.height <= 0 ||
      map.cells.size() !=
          static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height))
    throw std::invalid_argument("distance field: empty map");
  if (map.origin.theta != 0.0)
    throw std::invalid_argument(
        "distance field: the map's origin has a yaw; the field's box is axis-aligned");
  OccupancyBox out;
  out.dimensions = 2;
  out.shape = {static_cast<std::size_t>(map.width), static_cast<std::size_t>(map.height), 1};
  priceBox(out.shape, 2, map.resolution, params);
  out.resolution = map.resolution;
  out.origin = Eigen::Vector3d(map.origin.x + 0.5 * map.resolution,
                               map.origin.y + 0.5 * map.resolution, 0.0);
  out.state.resize(out.voxels());
  const std::size_t w = out.shape[0], h = out.shape[1];
  for (std::size_t i = 0; i < w; ++i) {
    for (std::size_t j = 0; j < h; ++j) {
      const std::int8_t c = map.cells[j * w + i];
      out.state[i * h + j] = c == kCellOccupied  ? kVoxelOccupied
                             : c == kCellUnknown ? kVoxelUnknown
                                                 : kVoxelFree;
    }
  }
  return out;
}

OccupancyBox occupancyBoxOfPoints(const float* xyz, std::size_t stride_bytes, std::size_t count,
                                  double resolution, const DistanceFieldParams& params) {
  if (!(resolution >= kOctomapMinResolution && resolution <= kOctomapMaxResolution)) {
    std::ostringstream msg;
    msg << "distance field: resolution must be in [" << kOctomapMinResolution << ", "
        << kOctomapMaxResolution << "] m (the cell edges a map file can hold), got " << resolution;
    throw std::invalid_argument(msg.str());
  }
  const auto* bytes = reinterpret_cast<const unsigned char*>(xyz);
  const double inv = 1.0 / resolution;
  std::vector<VoxelKey> keys;
  keys.reserve(xyz == nullptr ? 0 : count);
  VoxelKey lo{std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::max(),
              std::numeric_limits<std::int64_t>::max()};
  VoxelKey hi{std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::min(),
              std::numeric_limits<std::int64_t>::min()};
  for (std::size_t n = 0; xyz != nullptr && n < count; ++n) {
    const auto* p = reinterpret_cast<const float*>(bytes + n * stride_bytes);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
    const Eigen::Vector3d q(p[0], p[1], p[2]);
    const Eigen::Array3i c = voxelOfScaled(q.array() * inv, q);
    const VoxelKey k{c.x(), c.y(), c.z()};
    lo = {std::min(lo.x, k.x), std::min(lo.y, k.y), std::min(lo.z, k.z)};
    hi = {std::max(hi.x, k.x), std::max(hi.y, k.y), std::max(hi.z, k.z)};
    keys.push_back(k);
  }
  if (keys.empty()) throw std::invalid_argument("distance field: no finite point in the map");
  OccupancyBox out;
  out.dimensions = 3;
  out.shape = {static_cast<std::size_t>(hi.x - lo.x + 1), static_cast<std::size_t>(hi.y - lo.y + 1),
               static_cast<std::size_t>(hi.z - lo.z + 1)};
  priceBox(out.shape, 3, resolution, params);
  out.resolution = resolution;
  out.min_key = {lo.x, lo.y, lo.z};
  out.origin = (Eigen::Vector3d(lo.x, lo.y, lo.z) + Eigen::Vector3d::Constant(0.5)) * resolution;
  out.state.assign(out.voxels(), kVoxelFree);
  for (const VoxelKey& k : keys) {
    out.state[(static_cast<std::size_t>(k.x - lo.x) * out.shape[1] +
               static_cast<std::size_t>(k.y - lo.y)) *
                  out.shape[2] +
              static_cast<std::size_t>(k.z - lo.z)] = kVoxelOccupied;
  }
  return out;
}

}  // namespace metricmap
