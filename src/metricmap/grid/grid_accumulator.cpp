#include "metricmap/grid/grid_accumulator.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/byte_buffer.h"
#include "metricmap/common/tile_owner.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

constexpr std::uint32_t kMagic = 0x4147'4D4Du;  // "MMGA" read as little-endian bytes
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kCellBytes = 3 * 8 + 8 + 3 * 8;
constexpr std::int64_t kMaxIndex = std::int64_t{4'000'000'000'000'000'000};  // as the kernel

bool linearLess(const CellSum& a, const CellSum& b) {
  if (a.index[2] != b.index[2]) return a.index[2] < b.index[2];
  if (a.index[1] != b.index[1]) return a.index[1] < b.index[1];
  return a.index[0] < b.index[0];
}

void putHeader(ByteWriter& w, float cell, std::uint64_t input, std::uint64_t skipped,
               std::uint64_t cells) {
  w.put(kMagic);
  w.put(kVersion);
  w.put(cell);
  w.put(std::uint32_t{0});  // padding, keeps the layout explicit
  w.put(input);
  w.put(skipped);
  w.put(cells);
}

/// Writes one cell record (kCellBytes) at `dst`; returns the end.
std::uint8_t* putCell(std::uint8_t* dst, const CellSum& c) {
  std::memcpy(dst, c.index.data(), 24);
  std::memcpy(dst + 24, &c.count, 8);
  std::memcpy(dst + 32, c.sum.data(), 24);
  return dst + kCellBytes;
}

/// Merges the sorted runs of `cells` that start at `starts` (ascending, starts[0] = 0), pairwise
/// and stably: the order of equal cells is their order in `cells`, as a stable sort gives.
void mergeRuns(std::vector<CellSum>& cells, std::vector<std::size_t> starts) {
  starts.push_back(cells.size());
  while (starts.size() > 2) {
    std::vector<std::size_t> next;
    for (std::size_t r = 0; r + 1 < starts.size(); r += 2) {
      next.push_back(starts[r]);
      if (r + 2 < starts.size()) {
        std::inplace_merge(cells.begin() + static_cast<std::ptrdiff_t>(starts[r]),
                           cells.begin() + static_cast<std::ptrdiff_t>(starts[r + 1]),
                           cells.begin() + static_cast<std::ptrdiff_t>(starts[r + 2]), linearLess);
      }
    }
    next.push_back(cells.size());
    starts.swap(next);
  }
}

}  // namespace

GridAccumulator::GridAccumulator(float cell_size) : cell_size_(cell_size) {
  validateCellSize(cell_size);
}

void GridAccumulator::add(const GridResult& part, std::uint64_t input_points) {
  const GridLayout& L = part.layout;
  if (!part.cells.empty() &&
      (L.cell_size != static_cast<double>(cell_size_) || L.origin != Eigen::Vector3d::Zero())) {
    std::ostringstream os;
    os << "GridAccumulator: a part must be a WorldAligned build at cell size " << cell_size_
       << " (got cell size " << L.cell_size << ")";
    throw std::invalid_argument(os.str());
  }
  input_points_ += input_points;
  skipped_points_ += part.stats.skipped_points;
  cells_.reserve(cells_.size() + part.cells.size());
  for (const GridCell& c : part.cells) {
    const double n = static_cast<double>(c.count);
    cells_.push_back({c.index, c.count, {c.mean.x() * n, c.mean.y() * n, c.mean.z() * n}});
  }
  sorted_ = false;
}

void GridAccumulator::merge(const GridAccumulator& other) {
  if (other.cell_size_ != cell_size_) {
    std::ostringstream os;
    os << "GridAccumulator: cannot merge cell size " << other.cell_size_ << " into " << cell_size_;
    throw std::invalid_argument(os.str());
  }
  if (&other == this) throw std::invalid_argument("GridAccumulator: cannot merge with itself");
  input_points_ += other.input_points_;
  skipped_points_ += other.skipped_points_;
  cells_.insert(cells_.end(), other.cells_.begin(), other.cells_.end());
  sorted_ = false;
}

void GridAccumulator::normalize() const {
  if (sorted_) return;
  // Parts arrive sorted (a build's cells, a buffer's): merge their runs; sort anything else.
  constexpr std::size_t kMaxRuns = 64;
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 1; i < cells_.size() && starts.size() <= kMaxRuns; ++i) {
    if (linearLess(cells_[i], cells_[i - 1])) starts.push_back(i);
  }
  if (starts.size() <= kMaxRuns) {
    mergeRuns(cells_, starts);
  } else {
    std::stable_sort(cells_.begin(), cells_.end(), linearLess);
  }
  std::size_t out = 0;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    if (out > 0 && cells_[out - 1].index == cells_[i].index) {
      CellSum& c = cells_[out - 1];
      c.count += cells_[i].count;
      for (int a = 0; a < 3; ++a) c.sum[a] += cells_[i].sum[a];
    } else {
      cells_[out++] = cells_[i];
    }
  }
  cells_.resize(out);
  sorted_ = true;
}

std::size_t GridAccumulator::cellCount() const {
  normalize();
  return cells_.size();
}

const std::vector<CellSum>& GridAccumulator::cells() const {
  normalize();
  return cells_;
}

std::vector<std::uint8_t> GridAccumulator::serialize() const {
  normalize();
  std::vector<std::uint8_t> out;
  out.reserve(40 + cells_.size() * kCellBytes);
  ByteWriter w(out);
  putHeader(w, cell_size_, input_points_, skipped_points_, cells_.size());
  out.resize(out.size() + cells_.size() * kCellBytes);
  std::uint8_t* dst = out.data() + out.size() - cells_.size() * kCellBytes;
  for (const CellSum& c : cells_) dst = putCell(dst, c);
  return out;
}

std::vector<std::vector<std::uint8_t>> GridAccumulator::serializeByOwner(unsigned parts) const {
  if (parts == 0) throw std::invalid_argument("GridAccumulator: zero parts");
  normalize();
  std::vector<std::uint64_t> counts(parts, 0);
  std::vector<unsigned> owner(cells_.size());
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const auto& k = cells_[i].index;
    owner[i] = tileOwner(k[0], k[1], k[2], parts);
    ++counts[owner[i]];
  }
  std::vector<std::vector<std::uint8_t>> out(parts);
  for (unsigned p = 0; p < parts; ++p) {
    out[p].reserve(40 + counts[p] * kCellBytes);
    ByteWriter w(out[p]);
    putHeader(w, cell_size_, p == 0 ? input_points_ : 0, p == 0 ? skipped_points_ : 0, counts[p]);
  }
  std::vector<std::uint8_t*> dst(parts);
  for (unsigned p = 0; p < parts; ++p) {
    const std::size_t at = out[p].size();
    out[p].resize(at + counts[p] * kCellBytes);
    dst[p] = out[p].data() + at;
  }
  for (std::size_t i = 0; i < cells_.size(); ++i) dst[owner[i]] = putCell(dst[owner[i]], cells_[i]);
  return out;
}

GridAccumulator GridAccumulator::deserialize(const std::uint8_t* data, std::size_t size,
                                             const std::string& what) {
  ByteReader r(data, size, what);
  if (r.get<std::uint32_t>() != kMagic) r.fail("not a grid accumulator buffer (bad magic)");
  const std::uint32_t version = r.get<std::uint32_t>();
  if (version != kVersion)
    r.fail("grid accumulator version " + std::to_string(version) + ", expected " +
           std::to_string(kVersion));
  const float cell = r.get<float>();
  if (!std::isfinite(cell) || !(cell > 0.0f)) r.fail("bad cell size");
  r.get<std::uint32_t>();
  GridAccumulator acc(cell);
  acc.input_points_ = r.get<std::uint64_t>();
  acc.skipped_points_ = r.get<std::uint64_t>();
  const std::uint64_t n = r.get<std::uint64_t>();
  if (n > r.remaining() / kCellBytes || r.remaining() != n * kCellBytes)
    r.fail("holds " + std::to_string(r.remaining()) + " bytes of cells, not " + std::to_string(n) +
           " cells of " + std::to_string(kCellBytes) + " bytes");
  acc.cells_.resize(n);
  for (CellSum& c : acc.cells_) {
    for (std::int64_t& i : c.index) {
      i = r.get<std::int64_t>();
      if (i > kMaxIndex || i < -kMaxIndex) r.fail("cell index out of range");
    }
    c.count = r.get<std::uint64_t>();
    if (c.count == 0) r.fail("a cell with no points");
    for (double& s : c.sum) {
      s = r.get<double>();
      if (!std::isfinite(s)) r.fail("a non-finite cell sum");
    }
  }
  // sorted and without repeated cells (a buffer may hold a cell twice: normalize combines it)
  acc.sorted_ = std::adjacent_find(acc.cells_.begin(), acc.cells_.end(),
                                   [](const CellSum& a, const CellSum& b) {
                                     return !linearLess(a, b);
                                   }) == acc.cells_.end();
  return acc;
}

GridSummary GridAccumulator::summary() const {
  normalize();
  GridSummary m;
  m.input_points = input_points_;
  m.skipped_points = skipped_points_;
  m.cells = cells_.size();
  if (cells_.empty()) return m;
  m.min_index = m.max_index = cells_.front().index;
  for (const CellSum& c : cells_) {
    m.points += c.count;
    for (int a = 0; a < 3; ++a) {
      m.min_index[a] = std::min(m.min_index[a], c.index[a]);
      m.max_index[a] = std::max(m.max_index[a], c.index[a]);
    }
  }
  return m;
}

GridResult gridStatisticsOf(const GridSummary& m, float cell_size) {
  GridResult res;
  res.stats.skipped_points = m.skipped_points;
  if (m.cells == 0) return res;
  GridLayout& L = res.layout;
  L.cell_size = cell_size;
  L.origin = Eigen::Vector3d::Zero();
  std::uint64_t total = 1;
  bool overflow = false;
  for (int a = 0; a < 3; ++a) {
    L.min_index[a] = m.min_index[a];
    L.dims[a] = static_cast<std::uint64_t>(m.max_index[a] - m.min_index[a]) + 1;
    overflow = overflow || __builtin_mul_overflow(total, L.dims[a], &total);
  }
  if (overflow || total == std::numeric_limits<std::uint64_t>::max()) {
    std::ostringstream os;
    os << "grid of " << L.dims[0] << " x " << L.dims[1] << " x " << L.dims[2]
       << " cells at cell size " << cell_size << " does not fit in 64 bits";
    throw CapacityError(os.str());
  }
  GridStatistics& s = res.stats;
  s.total_cells = total;
  s.occupied_cells = m.cells;
  s.empty_cells = total - m.cells;
  s.points = m.points;
  s.mean_points_per_occupied_cell = static_cast<double>(m.points) / static_cast<double>(m.cells);
  return res;
}

GridResult GridAccumulator::result() const {
  GridResult res = gridStatisticsOf(summary(), cell_size_);
  res.cells.reserve(cells_.size());
  for (const CellSum& c : cells_) {
    GridCell g;
    g.index = c.index;
    g.count = c.count;
    g.mean = Eigen::Vector3d(c.sum[0], c.sum[1], c.sum[2]) / static_cast<double>(c.count);
    res.cells.push_back(g);
  }
  return res;
}

}  // namespace metricmap
