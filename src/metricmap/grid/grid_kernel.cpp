#include "metricmap/grid/grid_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/bounds.h"
#include "metricmap/common/cell_table.h"
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

struct Accumulator {
  double sx = 0.0, sy = 0.0, sz = 0.0;
  std::uint64_t count = 0;
  std::size_t first = 0;
};

std::string tooLarge(const GridLayout& layout, float cell) {
  std::ostringstream os;
  os << "grid of " << layout.dims[0] << " x " << layout.dims[1] << " x " << layout.dims[2]
     << " cells at cell size " << cell << " does not fit in 64 bits";
  return os.str();
}

void checkAxis(double cells, float cell_size) {
  if (!(cells < kMaxAxisIndex)) {
    std::ostringstream os;
    os << "cell size " << cell_size << " is too small for the cloud's coordinates ("
       << cells << " cells along one axis)";
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
      layout.dims[a] = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) -
                                                  layout.min_index[a]) + 1;
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

}  // namespace

void validateCellSize(float cell_size) {
  if (!std::isfinite(cell_size) || !(cell_size > 0.0f)) {
    std::ostringstream os;
    os << "cell size must be a finite number > 0, got " << cell_size;
    throw std::invalid_argument(os.str());
  }
}

GridResult buildGrid(const PointSpan& points, const GridParams& params) {
  validateCellSize(params.cell_size);
  GridResult result;
  const Bounds bounds = computeBounds(points);
  result.stats.skipped_points = points.size - bounds.finite;
  if (bounds.finite == 0) return result;

  result.layout = makeLayout(bounds, params);
  const GridLayout& L = result.layout;
  result.stats.total_cells = totalCells(L, params.cell_size);

  const std::uint64_t nx = L.dims[0], nxy = L.dims[0] * L.dims[1];
  const double cell = params.cell_size;
  const float inv = 1.0f / params.cell_size;
  const bool cloud_min = params.origin == GridOrigin::CloudMinimum;
  const double mn[3] = {bounds.min[0], bounds.min[1], bounds.min[2]};

  CellTable table(std::min<std::size_t>(bounds.finite, 1u << 16));
  std::vector<Accumulator> acc;
  std::uint64_t last_key = CellTable::kEmpty;
  std::size_t last_id = 0;
  for (std::size_t i = 0; i < points.size; ++i) {
    const float* p = points.at(i);
    if (!isFinitePoint(p)) continue;
    std::uint64_t k[3];
    for (int a = 0; a < 3; ++a) {
      k[a] = cloud_min ? static_cast<std::uint64_t>(snappedFloor(p[a], mn[a], cell))
                       : static_cast<std::uint64_t>(
                             static_cast<std::int64_t>(std::floor(p[a] * inv)) - L.min_index[a]);
    }
    const std::uint64_t key = k[0] + nx * k[1] + nxy * k[2];
    if (key != last_key) {
      last_key = key;
      last_id = table.findOrInsert(key, acc.size());
      if (last_id == acc.size()) {
        acc.emplace_back();
        acc.back().first = points.sourceIndex(i);
      }
    }
    Accumulator& a = acc[last_id];
    a.sx += p[0];
    a.sy += p[1];
    a.sz += p[2];
    ++a.count;
  }

  std::vector<std::pair<std::uint64_t, std::size_t>> order = table.entries();
  std::sort(order.begin(), order.end());
  result.cells.reserve(order.size());
  for (const auto& [key, id] : order) {
    const Accumulator& a = acc[id];
    GridCell c;
    c.index = {L.min_index[0] + static_cast<std::int64_t>(key % nx),
               L.min_index[1] + static_cast<std::int64_t>((key / nx) % L.dims[1]),
               L.min_index[2] + static_cast<std::int64_t>(key / nxy)};
    c.count = a.count;
    c.mean = Eigen::Vector3d(a.sx, a.sy, a.sz) / static_cast<double>(a.count);
    c.first_point = a.first;
    result.cells.push_back(c);
  }
  GridStatistics& s = result.stats;
  s.points = bounds.finite;
  s.occupied_cells = result.cells.size();
  s.empty_cells = s.total_cells - s.occupied_cells;
  s.mean_points_per_occupied_cell =
      static_cast<double>(s.points) / static_cast<double>(s.occupied_cells);
  return result;
}

}  // namespace metricmap
