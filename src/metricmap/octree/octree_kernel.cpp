#include "metricmap/octree/octree_kernel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "metricmap/detail/bounds.h"
#include "metricmap/detail/fast_floor.h"
#include "metricmap/detail/huge_pages.h"
#include "metricmap/detail/parallel.h"
#include "metricmap/detail/simd_points.h"
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
  double scale[3];                // 2^table_levels / extent (0 for a flat axis)

  void buildTables() {
    table_levels = std::min(levels, kTableLevels);
    const std::size_t n = std::size_t{1} << table_levels;
    for (int a = 0; a < 3; ++a) {
      std::vector<double>& b = breaks[a];
      b.assign(n + 1, 0.0);
      scale[a] = max[a] > min[a] ? static_cast<double>(n) / (max[a] - min[a]) : 0.0;
      b[0] = min[a];
      b[n] = max[a];
      for (std::size_t step = n; step > 1; step /= 2) {
        for (std::size_t i = step / 2; i < n; i += step)
          b[i] = (b[i - step / 2] + b[i + step / 2]) / 2;
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
      const std::int64_t t = floorToInt((p - min[a]) * scale[a]);
      j = t <= 0 ? 0 : std::min<std::size_t>(top, static_cast<std::size_t>(t));
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
  // Key depth: the first level whose nodes cannot split. Halving rounds, so a node's edge at
  // depth d is max_ext / 2^d within a relative 2^-40; the margin keeps every node that may
  // split above this level. The split test itself looks at each node's own edges.
  const double limit = static_cast<double>(params.min_cell_size) * (1.0 - 1e-9);
  f.levels = 0;
  while (f.levels < kOctreeMaxDepth && std::ldexp(max_ext, -static_cast<int>(f.levels)) > limit) {
    ++f.levels;
  }
  f.buildTables();
  return f;
}

bool insideRoot(const float* p, const Frame& f) {
  for (int a = 0; a < 3; ++a) {
    if (p[a] < f.min[a] || p[a] > f.max[a]) return false;
  }
  return true;
}

/// The Morton keys of a whole cloud (loadsFourFloats) when every level is in the breakpoint
/// tables and no axis is flat: the table position is estimated for x, y, z at once in SSE2
/// float arithmetic and then settled exactly against the tables in double, as quantize() does
/// (the settled position does not depend on the estimate). False when it does not apply.
bool mortonKeysFastApplies(const PointSpan& points, const Frame& f, const OctreeParams& params) {
#if defined(__SSE2__)
  if (!loadsFourFloats(points) || params.has_root_box || f.table_levels != f.levels ||
      f.levels > 16) {
    return false;
  }
  for (int a = 0; a < 3; ++a) {
    if (!(f.max[a] > f.min[a])) return false;
  }
  return true;
#else
  (void)points, (void)f, (void)params;
  return false;
#endif
}

/// Morton keys of points [begin, end) (when mortonKeysFastApplies).
template <typename Sink>
void mortonKeysFast(const PointSpan& points, std::size_t begin, std::size_t end, const Frame& f,
                    Sink& sink) {
#if defined(__SSE2__)
  static const std::array<std::uint64_t, 256> spread8 = [] {
    std::array<std::uint64_t, 256> t{};
    for (std::uint64_t i = 0; i < 256; ++i) t[i] = spreadBits(i);
    return t;
  }();
  const std::size_t top = f.breaks[0].size() - 2;
  const __m128 vmin = _mm_setr_ps(static_cast<float>(f.min[0]), static_cast<float>(f.min[1]),
                                  static_cast<float>(f.min[2]), 0.0f);
  const __m128 vscale = _mm_setr_ps(static_cast<float>(f.scale[0]), static_cast<float>(f.scale[1]),
                                    static_cast<float>(f.scale[2]), 0.0f);
  const __m128 vtop = _mm_set1_ps(static_cast<float>(top));
  const __m128 zero = _mm_setzero_ps();
  const double* breaks[3] = {f.breaks[0].data(), f.breaks[1].data(), f.breaks[2].data()};
  for (std::size_t i = begin; i < end; ++i) {
    const float* p = points.at(i);
    const __m128 v = _mm_loadu_ps(p);
    if (!finiteXyz(v)) continue;
    const __m128 e = _mm_min_ps(_mm_max_ps(_mm_mul_ps(_mm_sub_ps(v, vmin), vscale), zero), vtop);
    alignas(16) std::int32_t est[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(est), _mm_cvttps_epi32(e));
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a) {
      const double* b = breaks[a];
      const double pd = p[a];
      auto j = static_cast<std::size_t>(est[a]);
      while (j < top && b[j + 1] <= pd) ++j;
      while (j > 0 && b[j] > pd) --j;
      key |= (spread8[j & 255] | spread8[(j >> 8) & 255] << 24) << a;
    }
    sink.push(key, static_cast<std::uint32_t>(i));
  }
#else
  (void)points, (void)begin, (void)end, (void)f, (void)sink;
#endif
}

/// Nodes to reserve (address space only: pages are touched as nodes are written) so that the
/// node array rarely moves: a bound on the nodes of the tree, as far as it stays under 1 GiB.
/// Split nodes hold more than max_points points each and are disjoint within a level, so each
/// level has at most n / (max_points + 1) of them, each with 8 children.
std::size_t nodeReserve(std::size_t n, std::size_t max_points, unsigned levels) {
  constexpr std::size_t kMaxBytes = std::size_t{1} << 30;
  const std::size_t per_level = n / (std::max<std::size_t>(max_points, 1)) + 1;
  const double bound = 1.0 + 8.0 * static_cast<double>(per_level) * std::max(levels, 1u);
  const double cap = static_cast<double>(kMaxBytes / sizeof(OctreeNode));
  return static_cast<std::size_t>(std::min(bound, cap));
}

}  // namespace

void validateOctreeParams(const OctreeParams& params) {
  if (!std::isfinite(params.min_cell_size) || params.min_cell_size < 0.0f) {
    std::ostringstream os;
    os << "min cell size must be a finite number >= 0, got " << params.min_cell_size;
    throw std::invalid_argument(os.str());
  }
  if (params.has_root_box && (!params.root_min.allFinite() || !params.root_max.allFinite() ||
                              (params.root_max.array() < params.root_min.array()).any())) {
    throw std::invalid_argument("octree root box must be finite with max >= min");
  }
}

OctreeResult buildOctree(const PointSpan& points, const OctreeParams& params) {
  OctreeWorkspace workspace;
  OctreeResult result;
  buildOctree(points, params, workspace, result);
  return result;
}

namespace {

// Morton keys of the points inside the root at leaf level `frame.levels`, radix-sorted; the
// points' source indices in that order go to r.point_order.
void sortPointKeys(const PointSpan& points, const OctreeParams& params, const Frame& frame,
                   unsigned threads, KeySorter& sorter, OctreeResult& r) {
  sorter.reset(points.size, 3 * static_cast<int>(frame.levels));
  const bool fast = mortonKeysFastApplies(points, frame, params);
  sorter.fillParallel(points.size, threads, [&](std::size_t begin, std::size_t end, auto& sink) {
    if (fast) {
      mortonKeysFast(points, begin, end, frame, sink);
      return;
    }
    for (std::size_t i = begin; i < end; ++i) {
      const float* p = points.at(i);
      if (!isFinitePoint(p) || (params.has_root_box && !insideRoot(p, frame))) continue;
      sink.push(spreadBits(frame.quantize(0, p[0])) | spreadBits(frame.quantize(1, p[1])) << 1 |
                    spreadBits(frame.quantize(2, p[2])) << 2,
                static_cast<std::uint32_t>(i));
    }
  });
  sorter.sort(threads);
  const std::size_t n = sorter.size();
  r.stats.skipped_points = points.size - n;
  reserveHuge(r.point_order, n);
  r.point_order.resize(n);
  parallelRun(threads, [&](unsigned t) {
    const auto [begin, end] = chunkOf(n, threads, t);
    for (std::size_t k = begin; k < end; ++k) {
      r.point_order[k] = static_cast<std::uint32_t>(points.sourceIndex(sorter.position(k)));
    }
  });
}

// First position in [begin, end) whose octant digit at `shift` exceeds c (keys are sorted): a
// forward scan for short ranges, a binary search for long ones.
std::size_t octantEnd(const KeySorter& sorter, std::size_t begin, std::size_t end, unsigned shift,
                      unsigned c) {
  std::size_t lo = begin, hi = end;
  if (hi - lo <= 32) {
    while (lo < hi && ((sorter.key(lo) >> shift) & 7u) <= c) ++lo;
    return lo;
  }
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (((sorter.key(mid) >> shift) & 7u) <= c) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

// Top-down build over the sorted keys; children of a node are 8 consecutive ranges.
void splitNodes(const OctreeParams& params, const Frame& frame, const KeySorter& sorter,
                OctreeWorkspace& workspace, OctreeResult& r) {
  const std::size_t n = sorter.size();
  r.root.min = Eigen::Vector3d(frame.min[0], frame.min[1], frame.min[2]);
  r.root.max = Eigen::Vector3d(frame.max[0], frame.max[1], frame.max[2]);
  OctreeNode root;
  root.count = static_cast<std::uint32_t>(n);
  reserveHuge(r.nodes, nodeReserve(n, params.max_points_per_leaf, frame.levels));
  r.nodes.push_back(root);
  std::vector<OctreeWorkspace::Pending>& stack = workspace.stack;
  stack.assign(1, {0, r.root});
  while (!stack.empty()) {
    const auto [id, box] = stack.back();
    stack.pop_back();
    const OctreeNode node = r.nodes[id];
    const bool split = node.count > params.max_points_per_leaf && node.depth < frame.levels &&
                       (box.max - box.min).maxCoeff() > params.min_cell_size;
    if (!split) {
      // Popped in depth-first order (children are pushed 7..0), so leaves come in Morton order.
      if (node.count > 0) r.occupied_leaves.push_back(id);
      continue;
    }
    if (r.nodes.size() > OctreeNode::kNone - 9) throw CapacityError("octree: 2^32 nodes or more");
    const unsigned shift = 3 * (frame.levels - 1 - node.depth);
    if (r.nodes.size() + 8 > r.nodes.capacity()) {  // grow by doubling, on huge pages
      reserveHuge(r.nodes, std::max<std::size_t>(4096, 2 * r.nodes.capacity()));
    }
    const auto first_child = static_cast<std::uint32_t>(r.nodes.size());
    r.nodes[id].first_child = first_child;
    std::size_t begin = node.first_point;
    const std::size_t end = begin + node.count;
    for (unsigned c = 0; c < 8; ++c) {
      const std::size_t lo = octantEnd(sorter, begin, end, shift, c);
      OctreeNode child;
      child.depth = node.depth + 1;
      child.parent = static_cast<std::uint32_t>(id);
      child.first_point = static_cast<std::uint32_t>(begin);
      child.count = static_cast<std::uint32_t>(lo - begin);
      r.nodes.push_back(child);
      begin = lo;
    }
    for (unsigned c = 8; c-- > 0;) stack.push_back({first_child + c, childBox(box, c)});
  }
}

// Sums, kept in the nodes' mean fields until the means are taken: occupied leaves in Morton
// order cover the sorted points in one sweep, so the gather can prefetch ahead across leaves;
// then children into parents (children follow parents), and the statistics.
void sumNodes(const PointSpan& points, const KeySorter& sorter, unsigned threads, OctreeResult& r) {
  const std::size_t n = sorter.size();
  OctreeStatistics& s = r.stats;
  constexpr std::size_t kAhead = 48;  // prefetch distance, measured (docs/BENCHMARKS.md)
  // Leaf sums in parallel over contiguous runs of leaves (each leaf's sum is its own, in
  // sorted order); the point count is an integer sum.
  const std::size_t leaves = r.occupied_leaves.size();
  const unsigned sum_threads = resolveThreads(threads, n, std::size_t{1} << 17);
  std::vector<std::uint64_t> leaf_points(sum_threads, 0);
  parallelRun(sum_threads, [&](unsigned t) {
    const auto [first, last] = chunkOf(leaves, sum_threads, t);
    for (std::size_t j = first; j < last; ++j) {
      OctreeNode& node = r.nodes[r.occupied_leaves[j]];
      double sx = 0.0, sy = 0.0, sz = 0.0;
      const std::size_t end = std::size_t{node.first_point} + node.count;
      for (std::size_t k = node.first_point; k < end; ++k) {
        if (k + kAhead < n) __builtin_prefetch(points.at(sorter.position(k + kAhead)));
        const float* p = points.at(sorter.position(k));
        sx += p[0];
        sy += p[1];
        sz += p[2];
      }
      node.mean = Eigen::Vector3d(sx, sy, sz);
      leaf_points[t] += node.count;
    }
  });
  for (std::uint64_t c : leaf_points) s.points += c;
  // One sweep from the last node back: children come after their parents, so a node's sum is
  // complete when the sweep reaches it (then it is passed on to the parent).
  for (std::size_t id = r.nodes.size(); id-- > 0;) {
    OctreeNode& node = r.nodes[id];
    s.max_depth = std::max<unsigned>(s.max_depth, node.depth);
    if (!node.isLeaf()) {
      ++s.internal_nodes;
    } else if (node.count == 0) {
      ++s.empty_leaves;
    }
    const Eigen::Vector3d sum = node.mean;
    if (node.count > 0) node.mean = sum / static_cast<double>(node.count);
    if (id > 0) r.nodes[node.parent].mean += sum;
  }
  s.occupied_leaves = r.occupied_leaves.size();
  s.leaf_nodes = s.occupied_leaves + s.empty_leaves;
  s.total_nodes = r.nodes.size();
  if (s.occupied_leaves > 0) {
    s.mean_points_per_occupied_leaf =
        static_cast<double>(s.points) / static_cast<double>(s.occupied_leaves);
  }
}

}  // namespace

void buildOctree(const PointSpan& points, const OctreeParams& params, OctreeWorkspace& workspace,
                 OctreeResult& r) {
  validateOctreeParams(params);
  r.nodes.clear();
  r.point_order.clear();
  r.occupied_leaves.clear();
  r.stats = OctreeStatistics();
  const unsigned threads = resolveThreads(params.threads, points.size, std::size_t{1} << 17);
  const Bounds bounds = computeBounds(points, threads);
  const Frame frame = makeFrame(bounds, params);
  if (points.size > 0xFFFFFFFFull) throw CapacityError("octree: more than 2^32 points");
  sortPointKeys(points, params, frame, threads, workspace.sorter, r);
  splitNodes(params, frame, workspace.sorter, workspace, r);
  sumNodes(points, workspace.sorter, threads, r);
}

}  // namespace metricmap
