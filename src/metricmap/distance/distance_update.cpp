#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "metricmap/distance/distance_field.h"
#include "metricmap/distance/distance_work.h"
#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {

DistanceUpdateReport DistanceField::update(const LogOddsMap& map) {
  if (box_.dimensions != 3)
    throw std::invalid_argument("update: a 2D field cannot be updated from a 3D log-odds map");
  if (std::fabs(map.resolution() - box_.resolution) > 1e-9 * box_.resolution) {
    std::ostringstream msg;
    msg << "update: the map's resolution " << map.resolution() << " m differs from the field's "
        << box_.resolution << " m";
    throw std::invalid_argument(msg.str());
  }
  std::vector<std::pair<std::size_t, std::uint8_t>> changes;
  DistanceUpdateReport outside;
  const auto& s = box_.shape;
  const auto& k0 = box_.min_key;
  map.forEachBlock([&](std::uint64_t block_key, const std::uint64_t* known, const float* lo) {
    const VoxelKey b = unpackVoxelKey(block_key);
    for (int w = 0; w < detail::kBlockWords; ++w) {
      for (std::uint64_t bits = known[w]; bits != 0; bits &= bits - 1) {
        const int v = w * 64 + __builtin_ctzll(bits);
        const std::int64_t x = b.x * detail::kBlockEdge + (v & 7) - k0[0];
        const std::int64_t y = b.y * detail::kBlockEdge + ((v >> 3) & 7) - k0[1];
        const std::int64_t z = b.z * detail::kBlockEdge + (v >> 6) - k0[2];
        if (x < 0 || y < 0 || z < 0 || x >= static_cast<std::int64_t>(s[0]) ||
            y >= static_cast<std::int64_t>(s[1]) || z >= static_cast<std::int64_t>(s[2])) {
          ++outside.outside_voxels;
          continue;
        }
        const std::size_t at = index(static_cast<std::size_t>(x), static_cast<std::size_t>(y),
                                     static_cast<std::size_t>(z));
        const std::uint8_t state = map.isOccupied(lo[v]) ? kVoxelOccupied : kVoxelFree;
        if (box_.state[at] != state) changes.emplace_back(at, state);
      }
    }
  });
  DistanceUpdateReport report = updateStates(changes);
  report.outside_voxels = outside.outside_voxels;
  return report;
}

DistanceUpdateReport DistanceField::updateStates(
    const std::vector<std::pair<std::size_t, std::uint8_t>>& changes) {
  DistanceUpdateReport report;
  std::vector<std::size_t> lines;  // pass-1 lines (i * ny + j) holding a changed obstacle
  const bool two = params_.signed_distance;
  for (const auto& [at, state] : changes) {
    const std::uint8_t before = box_.state[at];
    if (before == state) continue;
    if (before == kVoxelUnknown) ++report.observed_voxels;
    box_.state[at] = state;
    const bool o = obstacleState(state);
    if ((work_->site[0][at] != 0) == o) continue;
    ++report.changed_voxels;
    work_->site[0][at] = o;
    if (two) work_->site[1][at] = !o;
    lines.push_back(at / box_.shape[2]);
  }
  if (report.changed_voxels == 0) {
    seconds_ = 0.0;
    return report;
  }
  std::sort(lines.begin(), lines.end());
  lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
  report.full = !params_.incremental;
  compute(report.full ? nullptr : &lines, report.lines);
  return report;
}

}  // namespace metricmap
