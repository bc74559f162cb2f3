#include "metricmap/grid/grid_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/bounds.h"
#include "metricmap/common/fast_floor.h"
#include "metricmap/common/huge_pages.h"
#include "metricmap/common/simd_points.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

constexpr double kMaxAxisIndex = 4.0e18;  // well inside int64
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

GridLayout makeLayout(const Bounds& b, const GridParams& params) {
  GridLayout layout;
  layout.cell_size = params.cell_size;
  const float inv = 1.0f / params.cell_size;
  for (int a = 0; a < 3; ++a) {
    if (params.origin == GridOrigin::CloudMinimum) {
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

/// WorldAligned keys of a whole cloud, x, y, z in one SSE2 register: floor(p * inv) in float
/// exactly as the scalar path (and pcl::VoxelGrid) computes it. False, doing nothing, unless
/// loadsFourFloats and every cell index is within +-2^30 (int32 conversions).
bool worldKeysFast(const PointSpan& points, float inv, const GridLayout& L, KeySorter& sorter) {
#if defined(__SSE2__)
  for (int a = 0; a < 3; ++a) {
    if (std::abs(L.min_index[a]) >= (1 << 30) || L.dims[a] >= (1u << 30)) return false;
  }
  if (!loadsFourFloats(points)) return false;
  const std::uint64_t nx = L.dims[0], nxy = L.dims[0] * L.dims[1];
  const __m128 scale = _mm_set1_ps(inv);
  const __m128i offset =
      _mm_setr_epi32(static_cast<int>(L.min_index[0]), static_cast<int>(L.min_index[1]),
                     static_cast<int>(L.min_index[2]), 0);
  for (std::size_t i = 0; i < points.size; ++i) {
    const __m128 v = loadPoint(points, i);
    if (!finiteXyz(v)) continue;
    const __m128 s = _mm_mul_ps(v, scale);
    __m128i t = _mm_cvttps_epi32(s);  // truncation; one less where that rounded up
    t = _mm_add_epi32(t, _mm_castps_si128(_mm_cmplt_ps(s, _mm_cvtepi32_ps(t))));
    alignas(16) std::int32_t k[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(k), _mm_sub_epi32(t, offset));
    sorter.push(static_cast<std::uint64_t>(k[0]) + nx * static_cast<std::uint64_t>(k[1]) +
                    nxy * static_cast<std::uint64_t>(k[2]),
                static_cast<std::uint32_t>(i));
  }
  return true;
#else
  (void)points, (void)inv, (void)L, (void)sorter;
  return false;
#endif
}

}  // namespace

void validateCellSize(float cell_size) {
  if (!std::isfinite(cell_size) || !(cell_size > 0.0f)) {
    std::ostringstream os;
    os << "cell size must be a finite number > 0, got " << cell_size;
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
  validateCellSize(params.cell_size);
  result.layout = GridLayout();
  result.cells.clear();
  result.stats = GridStatistics();
  const Bounds bounds = computeBounds(points);
  result.stats.skipped_points = points.size - bounds.finite;
  if (bounds.finite == 0) return;

  result.layout = makeLayout(bounds, params);
  const GridLayout& L = result.layout;
  result.stats.total_cells = totalCells(L, params.cell_size);

  const std::uint64_t nx = L.dims[0], nxy = L.dims[0] * L.dims[1];
  const double cell = params.cell_size;
  const float inv = 1.0f / params.cell_size;
  const bool cloud_min = params.origin == GridOrigin::CloudMinimum;
  const double mn[3] = {bounds.min[0], bounds.min[1], bounds.min[2]};
  if (points.size > 0xFFFFFFFFull) throw CapacityError("grid: more than 2^32 points");

  // Linear cell key of every finite point, then a radix sort: equal keys become runs.
  KeySorter& sorter = workspace.sorter;
  sorter.reset(points.size, bitsFor(result.stats.total_cells));
  if (cloud_min || !worldKeysFast(points, inv, L, sorter)) {
    for (std::size_t i = 0; i < points.size; ++i) {
      const float* p = points.at(i);
      if (!isFinitePoint(p)) continue;
      std::uint64_t k[3];
      for (int a = 0; a < 3; ++a) {
        k[a] = cloud_min ? snappedIndex(p[a], mn[a], cell)
                         : static_cast<std::uint64_t>(floorToInt(p[a] * inv) - L.min_index[a]);
      }
      sorter.push(k[0] + nx * k[1] + nxy * k[2], static_cast<std::uint32_t>(i));
    }
  }
  sorter.sort();

  const std::size_t n = sorter.size();
  std::size_t runs = n > 0 ? 1 : 0;
  for (std::size_t i = 1; i < n; ++i) runs += sorter.key(i) != sorter.key(i - 1);
  reserveHuge(result.cells, runs);

  constexpr std::size_t kAhead = 48;  // prefetch distance, measured (docs/BENCHMARKS.md)
  std::uint64_t row_start = 0;        // key of (0, iy, iz) for the row of the previous cell
  std::int64_t iy = 0, iz = 0;
  bool have_row = false;
  for (std::size_t begin = 0; begin < n;) {
    const std::uint64_t key = sorter.key(begin);
    double sx = 0.0, sy = 0.0, sz = 0.0;
    std::size_t end = begin;
    for (; end < n && sorter.key(end) == key; ++end) {
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
    result.cells.push_back(c);
    begin = end;
  }
  GridStatistics& s = result.stats;
  s.points = bounds.finite;
  s.occupied_cells = result.cells.size();
  s.empty_cells = s.total_cells - s.occupied_cells;
  s.mean_points_per_occupied_cell =
      static_cast<double>(s.points) / static_cast<double>(s.occupied_cells);
}

}  // namespace metricmap
