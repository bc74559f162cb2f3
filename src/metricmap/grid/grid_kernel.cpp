#include "metricmap/grid/grid_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

constexpr double kMaxAxisIndex = 4.0e18;           // well inside int64
constexpr std::size_t kPointsPerThread = 1 << 17;  // below this, another thread does not pay
// Float32 carries 24 significant bits; a point within that rounding of a cell boundary is
// treated as lying on it. Twice the bound, for margin.
constexpr double kFloatSnap = 1.0 / 8388608.0;  // 2^-23

/// floor((p - mn) / cell) for p >= mn, snapping float32 rounding onto the boundary above.
inline double snappedFloor(double p, double mn, double cell) {
  const double t = (p - mn) / cell;
  double f = std::floor(t);
  const double tol = ((std::fabs(p) + std::fabs(mn)) / cell + t) * kFloatSnap;
  if (f + 1.0 - t <= tol) f += 1.0;
  return f;
}

/// The same for a point known to be inside the checked bounds (no libm call).
inline std::uint64_t snappedIndex(double p, double mn, double cell) {
  const double t = (p - mn) / cell;
  std::int64_t f = floorToInt(t);
  const double tol = ((std::fabs(p) + std::fabs(mn)) / cell + t) * kFloatSnap;
  f += static_cast<std::int64_t>(static_cast<double>(f) + 1.0 - t <= tol);
  return static_cast<std::uint64_t>(f);
}

std::string tooLarge(const GridLayout& layout, float cell) {
  std::ostringstream os;
  os << "grid of " << layout.dims[0] << " x " << layout.dims[1] << " x " << layout.dims[2]
     << " cells at cell size " << cell << " does not fit in 64 bits";
  return os.str();
}

void checkAxis(double cells, float cell_size) {
  if (!(cells < kMaxAxisIndex)) {
    std::ostringstream os;
    os << "cell size " << cell_size << " is too small for the cloud's coordinates (" << cells
       << " cells along one axis)";
    throw CapacityError(os.str());
  }
}

/// Cells measured from the cloud's minimum snap float rounding onto the boundary above (up to
/// kFloatSnap of the coordinates in cells); past half a cell the snap would move points across
/// whole cells (the minimum itself out of cell 0): the cell is finer than the coordinates.
void checkSnap(double lo, double hi, double cell) {
  const double extent = (std::fabs(lo) + std::fabs(hi) + (hi - lo)) * kFloatSnap;
  if (!(extent / cell < 0.5)) {
    std::ostringstream os;
    os << "cell size " << static_cast<float>(cell)
       << " is finer than float32 resolves the cloud's coordinates (" << lo << " to " << hi
       << "): cells from the cloud's minimum need a cell size above " << 2.0 * extent;
    throw CapacityError(os.str());
  }
}

/// True for the origins computed in double from a start point (Point, HalfCellBelowMinimum).
bool startsAtPoint(GridOrigin origin) {
  return origin == GridOrigin::Point || origin == GridOrigin::HalfCellBelowMinimum;
}

double exactCell(const GridParams& params) {
  return params.exact_cell_size > 0.0 ? params.exact_cell_size : params.cell_size;
}

/// Start of cell (0, 0, 0) for the origins that start at a point.
Eigen::Vector3d startPoint(const Bounds& b, const GridParams& params) {
  if (params.origin == GridOrigin::Point) return params.origin_point;
  const double cell = exactCell(params);
  const Eigen::Vector3d cell3(cell, cell, cell);
  return Eigen::Vector3d(b.min[0], b.min[1], b.min[2]) - cell3 * 0.5;
}

GridLayout makeLayout(const Bounds& b, const GridParams& params) {
  GridLayout layout;
  layout.cell_size = params.cell_size;
  const float inv = 1.0f / params.cell_size;
  if (startsAtPoint(params.origin)) {
    const double cell = exactCell(params);
    layout.cell_size = cell;
    layout.origin = startPoint(b, params);
    for (int a = 0; a < 3; ++a) {
      const double lo = std::floor((b.min[a] - layout.origin[a]) / cell);
      const double hi = std::floor((b.max[a] - layout.origin[a]) / cell);
      checkAxis(std::fabs(lo), params.cell_size);
      checkAxis(std::fabs(hi), params.cell_size);
      layout.min_index[a] = static_cast<std::int64_t>(lo);
      layout.dims[a] =
          static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - layout.min_index[a]) + 1;
    }
    return layout;
  }
  for (int a = 0; a < 3; ++a) {
    if (params.origin == GridOrigin::CloudMinimum) {
      checkSnap(b.min[a], b.max[a], params.cell_size);
      const double hi = snappedFloor(b.max[a], b.min[a], params.cell_size);
      checkAxis(hi, params.cell_size);
      layout.min_index[a] = 0;
      layout.dims[a] = static_cast<std::uint64_t>(hi) + 1;
      layout.origin[a] = b.min[a];
    } else {
      const double lo = std::floor(b.min[a] * inv);
      const double hi = std::floor(b.max[a] * inv);
      checkAxis(std::fabs(lo), params.cell_size);
      checkAxis(std::fabs(hi), params.cell_size);
      layout.min_index[a] = static_cast<std::int64_t>(lo);
      layout.dims[a] =
          static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - layout.min_index[a]) + 1;
      layout.origin[a] = 0.0;
    }
  }
  return layout;
}

std::uint64_t totalCells(const GridLayout& layout, float cell) {
  std::uint64_t total = layout.dims[0];
  if (__builtin_mul_overflow(total, layout.dims[1], &total) ||
      __builtin_mul_overflow(total, layout.dims[2], &total) ||
      total == std::numeric_limits<std::uint64_t>::max()) {
    throw CapacityError(tooLarge(layout, cell));
  }
  return total;
}

/// True when the SSE2 WorldAligned key path applies: a whole cloud (loadsFourFloats) and every
/// cell index within +-2^30 (int32 conversions).
bool worldKeysFastApplies(const PointSpan& points, const GridLayout& L) {
#if defined(__SSE2__)
  for (int a = 0; a < 3; ++a) {
    if (std::abs(L.min_index[a]) >= (1 << 30) || L.dims[a] >= (1u << 30)) return false;
  }
  return loadsFourFloats(points);
#else
  (void)points, (void)L;
  return false;
#endif
}

/// WorldAligned keys of points [begin, end), x, y, z in one SSE2 register: floor(p * inv) in
/// float exactly as the scalar path (and pcl::VoxelGrid) computes it.
template <typename Sink>
void worldKeysFast(const PointSpan& points, std::size_t begin, std::size_t end, float inv,
                   const GridLayout& L, Sink& sink) {
#if defined(__SSE2__)
  const std::uint64_t nx = L.dims[0], nxy = L.dims[0] * L.dims[1];
  const __m128 scale = _mm_set1_ps(inv);
  const __m128i offset =
      _mm_setr_epi32(static_cast<int>(L.min_index[0]), static_cast<int>(L.min_index[1]),
                     static_cast<int>(L.min_index[2]), 0);
  for (std::size_t i = begin; i < end; ++i) {
    const __m128 v = loadPoint(points, i);
    if (!finiteXyz(v)) continue;
    const __m128 s = _mm_mul_ps(v, scale);
    __m128i t = _mm_cvttps_epi32(s);  // truncation; one less where that rounded up
    t = _mm_add_epi32(t, _mm_castps_si128(_mm_cmplt_ps(s, _mm_cvtepi32_ps(t))));
    alignas(16) std::int32_t k[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(k), _mm_sub_epi32(t, offset));
    sink.push(static_cast<std::uint64_t>(k[0]) + nx * static_cast<std::uint64_t>(k[1]) +
                  nxy * static_cast<std::uint64_t>(k[2]),
              static_cast<std::uint32_t>(i));
  }
#else
  (void)points, (void)begin, (void)end, (void)inv, (void)L, (void)sink;
#endif
}

/// Cells of the sorted keys [begin, end) (which start and end at key changes), in order, each
/// passed to `emit`.
template <typename Emit>
void accumulateCells(const PointSpan& points, const KeySorter& sorter, const GridLayout& L,
                     std::size_t begin_at, std::size_t end_at, Emit&& emit) {
  const std::uint64_t nx = L.dims[0], nxy = L.dims[0] * L.dims[1];
  const std::size_t n = sorter.size();
  constexpr std::size_t kAhead = 48;  // prefetch distance, measured (docs/NOTES.md)
  std::uint64_t row_start = 0;        // key of (0, iy, iz) for the row of the previous cell
  std::int64_t iy = 0, iz = 0;
  bool have_row = false;
  for (std::size_t begin = begin_at; begin < end_at;) {
    const std::uint64_t key = sorter.key(begin);
    double sx = 0.0, sy = 0.0, sz = 0.0;
    std::size_t end = begin;
    for (; end < end_at && sorter.key(end) == key; ++end) {
      if (end + kAhead < n) __builtin_prefetch(points.at(sorter.position(end + kAhead)));
      const float* p = points.at(sorter.position(end));
      sx += p[0];
      sy += p[1];
      sz += p[2];
    }
    if (!have_row || key - row_start >= nx) {  // sorted keys: most cells share the last row
      const std::uint64_t z = key / nxy, y = (key - z * nxy) / nx;
      iz = static_cast<std::int64_t>(z);
      iy = static_cast<std::int64_t>(y);
      row_start = z * nxy + y * nx;
      have_row = true;
    }
    GridCell c;
    c.index = {L.min_index[0] + static_cast<std::int64_t>(key - row_start), L.min_index[1] + iy,
               L.min_index[2] + iz};
    c.count = end - begin;
    c.mean = Eigen::Vector3d(sx, sy, sz) / static_cast<double>(c.count);
    c.first_point = points.sourceIndex(sorter.position(begin));
    emit(c);
    begin = end;
  }
}

/// Runs (distinct keys) among sorted keys [begin, end).
std::size_t countRuns(const KeySorter& sorter, std::size_t begin, std::size_t end) {
  std::size_t runs = end > begin ? 1 : 0;
  for (std::size_t i = begin + 1; i < end; ++i) runs += sorter.key(i) != sorter.key(i - 1);
  return runs;
}

}  // namespace

void validateCellSize(float cell_size) {
  if (!std::isfinite(cell_size) || !(cell_size > 0.0f)) {
    std::ostringstream os;
    os << "cell size must be a finite number > 0, got " << cell_size;
    throw std::invalid_argument(os.str());
  }
}

void validateGridParams(const GridParams& params) {
  validateCellSize(params.cell_size);
  if (params.exact_cell_size != 0.0 &&
      !(std::isfinite(params.exact_cell_size) && params.exact_cell_size > 0.0)) {
    std::ostringstream os;
    os << "cell size must be a finite number > 0, got " << params.exact_cell_size;
    throw std::invalid_argument(os.str());
  }
  if (params.origin == GridOrigin::Point && !params.origin_point.allFinite()) {
    std::ostringstream os;
    os << "grid origin must be finite, got (" << params.origin_point.x() << ", "
       << params.origin_point.y() << ", " << params.origin_point.z() << ")";
    throw std::invalid_argument(os.str());
  }
}

GridResult buildGrid(const PointSpan& points, const GridParams& params) {
  GridWorkspace workspace;
  GridResult result;
  buildGrid(points, params, workspace, result);
  return result;
}

void buildGrid(const PointSpan& points, const GridParams& params, GridWorkspace& workspace,
               GridResult& result) {
  validateGridParams(params);
  result.layout = GridLayout();
  result.cells.clear();
  result.stats = GridStatistics();
  result.point_cells.clear();
  if (params.point_cells) result.point_cells.assign(points.size, -1);
  const unsigned threads = resolveThreads(params.threads, points.size, kPointsPerThread);
  const Bounds bounds = computeBounds(points, threads);
  result.stats.skipped_points = points.size - bounds.finite;
  if (bounds.finite == 0) return;

  result.layout = makeLayout(bounds, params);
  const GridLayout& L = result.layout;
  result.stats.total_cells = totalCells(L, params.cell_size);

  const std::uint64_t nx = L.dims[0], nxy = L.dims[0] * L.dims[1];
  const double cell = params.cell_size;
  const float inv = 1.0f / params.cell_size;
  const bool cloud_min = params.origin == GridOrigin::CloudMinimum;
  const bool at_point = startsAtPoint(params.origin);
  const double exact = exactCell(params);
  const double mn[3] = {bounds.min[0], bounds.min[1], bounds.min[2]};
  if (points.size > 0xFFFFFFFFull) throw CapacityError("grid: more than 2^32 points");

  // Linear cell key of every finite point, then a radix sort: equal keys become runs.
  KeySorter& sorter = workspace.sorter;
  sorter.reset(points.size, bitsFor(result.stats.total_cells));
  const bool fast = !cloud_min && !at_point && worldKeysFastApplies(points, L);
  sorter.fillParallel(points.size, threads, [&](std::size_t begin, std::size_t end, auto& sink) {
    if (fast) {
      worldKeysFast(points, begin, end, inv, L, sink);
      return;
    }
    for (std::size_t i = begin; i < end; ++i) {
      const float* p = points.at(i);
      if (!isFinitePoint(p)) continue;
      std::uint64_t k[3];
      for (int a = 0; a < 3; ++a) {
        if (at_point) {
          const double t = (static_cast<double>(p[a]) - L.origin[a]) / exact;
          k[a] =
              static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(t)) - L.min_index[a]);
        } else {
          k[a] = cloud_min ? snappedIndex(p[a], mn[a], cell)
                           : static_cast<std::uint64_t>(floorToInt(p[a] * inv) - L.min_index[a]);
        }
      }
      sink.push(k[0] + nx * k[1] + nxy * k[2], static_cast<std::uint32_t>(i));
    }
  });
  sorter.sort(threads);

  // Cells: the sorted keys cut into one range per thread at key changes; each range's cells
  // are summed in sorted order, so the sums do not depend on the cut.
  const std::size_t n = sorter.size();
  std::vector<std::size_t> cuts(threads + 1, n);
  cuts[0] = 0;
  for (unsigned t = 1; t < threads; ++t) {
    std::size_t c = std::max(cuts[t - 1], chunkOf(n, threads, t).first);
    while (c > 0 && c < n && sorter.key(c) == sorter.key(c - 1)) ++c;
    cuts[t] = c;
  }
  std::vector<std::size_t> runs(threads);
  parallelRun(threads, [&](unsigned t) { runs[t] = countRuns(sorter, cuts[t], cuts[t + 1]); });
  std::vector<std::size_t> first_cell(threads + 1, 0);
  for (unsigned t = 0; t < threads; ++t) first_cell[t + 1] = first_cell[t] + runs[t];
  const std::size_t total_runs = first_cell[threads];
  reserveHuge(result.cells, total_runs);
  if (threads == 1) {
    accumulateCells(points, sorter, L, 0, n, [&](const GridCell& c) { result.cells.push_back(c); });
  } else {
    // Each thread writes its cells in place. Fresh pages are costly, so each first faults in
    // the pages it will write, beside the others, before the one (serial) resize.
    parallelRun(threads, [&](unsigned t) {
      touchPages(result.cells.data() + first_cell[t], runs[t] * sizeof(GridCell));
    });
    result.cells.resize(total_runs);
    parallelRun(threads, [&](unsigned t) {
      GridCell* out = result.cells.data() + first_cell[t];
      accumulateCells(points, sorter, L, cuts[t], cuts[t + 1],
                      [&out](const GridCell& c) { *out++ = c; });
    });
  }
  if (params.point_cells) {
    std::int64_t row = -1;
    for (std::size_t i = 0; i < n; ++i) {
      row += i == 0 || sorter.key(i) != sorter.key(i - 1);
      result.point_cells[sorter.position(i)] = row;
    }
  }
  GridStatistics& s = result.stats;
  s.points = bounds.finite;
  s.occupied_cells = result.cells.size();
  s.empty_cells = s.total_cells - s.occupied_cells;
  s.mean_points_per_occupied_cell =
      static_cast<double>(s.points) / static_cast<double>(s.occupied_cells);
}

}  // namespace metricmap
