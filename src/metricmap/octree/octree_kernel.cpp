#include "metricmap/octree/octree_kernel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/bounds.h"
#include "metricmap/common/radix_sort.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

/// Spread the low 21 bits of x so that bit b moves to bit 3b.
inline std::uint64_t spreadBits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

constexpr unsigned kTableLevels = 16;  // breakpoint tables hold at most 2^16 + 1 values per axis

/// The root volume, the number of levels that may split, and per axis the node boundaries of
/// the first levels. Boundaries are defined recursively, mid = (lo + hi) / 2 in double, exactly
/// as a recursive build computes them, so the Morton build makes the same decisions.
struct Frame {
  double min[3];
  double max[3];
  unsigned levels;  // depth of the Morton keys: no node at this depth or deeper can split
  unsigned table_levels;
  std::vector<double> breaks[3];  // 2^table_levels + 1 boundaries per axis

  void buildTables() {
    table_levels = std::min(levels, kTableLevels);
    const std::size_t n = std::size_t{1} << table_levels;
    for (int a = 0; a < 3; ++a) {
      std::vector<double>& b = breaks[a];
      b.assign(n + 1, 0.0);
      b[0] = min[a];
      b[n] = max[a];
      for (std::size_t step = n; step > 1; step /= 2) {
        for (std::size_t i = step / 2; i < n; i += step) b[i] = (b[i - step / 2] + b[i + step / 2]) / 2;
      }
    }
  }

  /// The leaf-level cell of coordinate p along axis a: the path of upper/lower decisions
  /// (p >= mid) from the root down `levels` levels, as bits.
  std::uint64_t quantize(int a, double p) const {
    const std::vector<double>& b = breaks[a];
    const std::size_t top = b.size() - 2;
    std::size_t j = top;
    if (max[a] > min[a]) {
      const double t = std::floor((p - min[a]) / (max[a] - min[a]) * static_cast<double>(top + 1));
      j = t <= 0.0 ? 0 : std::min<std::size_t>(top, static_cast<std::size_t>(t));
      while (j < top && b[j + 1] <= p) ++j;
      while (j > 0 && b[j] > p) --j;
    }
    std::uint64_t q = j;
    double lo = b[j], hi = b[j + 1];
    for (unsigned d = table_levels; d < levels; ++d) {
      const double mid = (lo + hi) / 2;
      const bool upper = p >= mid;
      q = (q << 1) | static_cast<std::uint64_t>(upper);
      (upper ? lo : hi) = mid;
    }
    return q;
  }
};

Frame makeFrame(const Bounds& b, const OctreeParams& params) {
  Frame f{};
  double max_ext = 0.0;
  for (int a = 0; a < 3; ++a) {
    f.min[a] = params.has_root_box ? params.root_min[a] : b.min[a];
    f.max[a] = params.has_root_box ? params.root_max[a] : b.max[a];
    max_ext = std::max(max_ext, f.max[a] - f.min[a]);
  }
  if (params.cubic_root) {
    for (int a = 0; a < 3; ++a) f.max[a] = f.min[a] + max_ext;
  }
  // Node edges are halved with rounding, so allow one level more than max_ext / 2^d suggests;
  // the split test itself looks at each node's own edges.
  f.levels = 0;
  while (f.levels < kOctreeMaxDepth &&
         std::ldexp(max_ext, -static_cast<int>(f.levels)) > params.min_cell_size) {
    ++f.levels;
  }
  if (max_ext > 0.0) f.levels = std::min(kOctreeMaxDepth, f.levels + 1);
  f.buildTables();
  return f;
}

bool insideRoot(const float* p, const Frame& f) {
  for (int a = 0; a < 3; ++a) {
    if (p[a] < f.min[a] || p[a] > f.max[a]) return false;
  }
  return true;
}

}  // namespace

void validateOctreeParams(const OctreeParams& params) {
  if (!std::isfinite(params.min_cell_size) || params.min_cell_size < 0.0f) {
    std::ostringstream os;
    os << "min cell size must be a finite number >= 0, got " << params.min_cell_size;
    throw std::invalid_argument(os.str());
  }
  if (params.has_root_box &&
      (!params.root_min.allFinite() || !params.root_max.allFinite() ||
       (params.root_max.array() < params.root_min.array()).any())) {
    throw std::invalid_argument("octree root box must be finite with max >= min");
  }
}

OctreeResult buildOctree(const PointSpan& points, const OctreeParams& params) {
  validateOctreeParams(params);
  OctreeResult r;
  const Bounds bounds = computeBounds(points);
  const Frame frame = makeFrame(bounds, params);

  // Morton keys of the points inside the root, leaf level `frame.levels`.
  std::vector<std::uint64_t> keys;
  keys.reserve(bounds.finite);
  r.point_order.reserve(bounds.finite);
  if (bounds.finite > 0xFFFFFFFFull) throw CapacityError("octree: more than 2^32 points");
  for (std::size_t i = 0; i < points.size; ++i) {
    const float* p = points.at(i);
    if (!isFinitePoint(p) || (params.has_root_box && !insideRoot(p, frame))) continue;
    keys.push_back(spreadBits(frame.quantize(0, p[0])) |
                   spreadBits(frame.quantize(1, p[1])) << 1 |
                   spreadBits(frame.quantize(2, p[2])) << 2);
    r.point_order.push_back(static_cast<std::uint32_t>(points.sourceIndex(i)));
  }
  radixSortPairs(keys, r.point_order, 3 * static_cast<int>(frame.levels));
  r.stats.skipped_points = points.size - keys.size();
  const std::size_t n = keys.size();

  // Top-down build over the sorted keys; children of a node are 8 consecutive ranges.
  OctreeNode root;
  root.min = Eigen::Vector3d(frame.min[0], frame.min[1], frame.min[2]);
  root.max = Eigen::Vector3d(frame.max[0], frame.max[1], frame.max[2]);
  root.count = n;
  r.nodes.push_back(root);
  std::vector<std::size_t> stack{0};
  while (!stack.empty()) {
    const std::size_t id = stack.back();
    stack.pop_back();
    const OctreeNode node = r.nodes[id];
    const bool split = node.count > params.max_points_per_leaf && node.depth < frame.levels &&
                       (node.max - node.min).maxCoeff() > params.min_cell_size;
    if (!split) continue;
    const unsigned shift = 3 * (frame.levels - 1 - node.depth);
    const std::size_t first_child = r.nodes.size();
    r.nodes[id].first_child = first_child;
    auto begin = keys.begin() + static_cast<std::ptrdiff_t>(node.first_point);
    const auto end = begin + static_cast<std::ptrdiff_t>(node.count);
    for (unsigned c = 0; c < 8; ++c) {
      const auto stop = std::partition_point(
          begin, end, [&](std::uint64_t k) { return ((k >> shift) & 7u) <= c; });
      OctreeNode child;
      child.depth = node.depth + 1;
      child.parent = id;
      child.first_point = static_cast<std::size_t>(begin - keys.begin());
      child.count = static_cast<std::uint64_t>(stop - begin);
      for (int a = 0; a < 3; ++a) {
        const double mid = (node.min[a] + node.max[a]) / 2;
        const bool upper = (c >> a) & 1u;
        child.min[a] = upper ? mid : node.min[a];
        child.max[a] = upper ? node.max[a] : mid;
      }
      r.nodes.push_back(child);
      begin = stop;
    }
    for (unsigned c = 8; c-- > 0;) stack.push_back(first_child + c);
  }

  // Sums: leaves from their points, then children into parents (children come after parents).
  std::vector<Eigen::Vector3d> sums(r.nodes.size(), Eigen::Vector3d::Zero());
  OctreeStatistics& s = r.stats;
  for (std::size_t id = 0; id < r.nodes.size(); ++id) {
    const OctreeNode& node = r.nodes[id];
    s.max_depth = std::max(s.max_depth, node.depth);
    if (!node.isLeaf()) {
      ++s.internal_nodes;
      continue;
    }
    ++s.leaf_nodes;
    if (node.count == 0) {
      ++s.empty_leaves;
      continue;
    }
    ++s.occupied_leaves;
    s.points += node.count;
    r.occupied_leaves.push_back(id);
    for (std::size_t k = node.first_point; k < node.first_point + node.count; ++k) {
      const float* p = reinterpret_cast<const float*>(reinterpret_cast<const char*>(points.base) +
                                         r.point_order[k] * points.stride);
      sums[id] += Eigen::Vector3d(p[0], p[1], p[2]);
    }
  }
  for (std::size_t id = r.nodes.size(); id-- > 1;) sums[r.nodes[id].parent] += sums[id];
  for (std::size_t id = 0; id < r.nodes.size(); ++id) {
    if (r.nodes[id].count > 0) r.nodes[id].mean = sums[id] / static_cast<double>(r.nodes[id].count);
  }
  std::sort(r.occupied_leaves.begin(), r.occupied_leaves.end(),
            [&](std::size_t a, std::size_t b) {
              return r.nodes[a].first_point < r.nodes[b].first_point;
            });
  s.total_nodes = r.nodes.size();
  if (s.occupied_leaves > 0) {
    s.mean_points_per_occupied_leaf =
        static_cast<double>(s.points) / static_cast<double>(s.occupied_leaves);
  }
  return r;
}

}  // namespace metricmap
