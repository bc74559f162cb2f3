#include "metricmap/slam/branch_and_bound_2d.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

std::uint8_t toByte(float p) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(p, 0.0f, 1.0f) * 255.0f));
}

/// Level d from level d - 1 (`prev`, cells of windows of `half` = 2^(d-1)): the window of 2^d
/// ending at k is the two windows of `half` ending at k and at k - half; cells beyond `prev`
/// are `pad`. Separable: along rows, then along columns.
void doubleLevel(const std::vector<std::uint8_t>& prev, std::int64_t pw, std::int64_t ph,
                 std::int64_t half, std::uint8_t pad, std::vector<std::uint8_t>& out,
                 std::int64_t w, std::int64_t h) {
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(w * ph));
  for (std::int64_t j = 0; j < ph; ++j) {
    const std::uint8_t* in = prev.data() + j * pw;
    std::uint8_t* o = rows.data() + j * w;
    for (std::int64_t i = 0; i < w; ++i) {
      const std::uint8_t a = i < pw ? in[i] : pad;
      const std::uint8_t b = i - half >= 0 && i - half < pw ? in[i - half] : pad;
      o[i] = std::max(a, b);
    }
  }
  out.assign(static_cast<std::size_t>(w * h), pad);
  for (std::int64_t j = 0; j < h; ++j) {
    std::uint8_t* o = out.data() + j * w;
    const bool has_a = j < ph, has_b = j - half >= 0 && j - half < ph;
    const std::uint8_t* a = has_a ? rows.data() + j * w : nullptr;
    const std::uint8_t* b = has_b ? rows.data() + (j - half) * w : nullptr;
    for (std::int64_t i = 0; i < w; ++i) o[i] = std::max(has_a ? a[i] : pad, has_b ? b[i] : pad);
  }
}

}  // namespace

BranchAndBoundMatcher2D::BranchAndBoundMatcher2D(const MatchGrid& grid, int depth,
                                                 std::uint64_t held)
    : i0_(grid.minI()), j0_(grid.minJ()), res_(grid.resolution()) {
  if (depth < 1 || depth > 16)
    throw std::invalid_argument("branch-and-bound depth must be in 1..16");
  outside_ = toByte(grid.table().min());
  const std::int64_t w = grid.width(), h = grid.height();
  std::uint64_t total = 0;
  for (int d = 0; d < depth; ++d) {
    const std::uint64_t pad = (std::uint64_t{1} << d) - 1;
    total += (static_cast<std::uint64_t>(w) + pad) * (static_cast<std::uint64_t>(h) + pad);
  }
  checkMemoryBeside(total, 1, held, "the loop-closure grids of a submap");
  levels_.resize(static_cast<std::size_t>(depth));
  Level& base = levels_[0];
  base.w = w;
  base.h = h;
  base.cells.resize(static_cast<std::size_t>(w * h));
  for (std::int64_t j = 0; j < h; ++j)
    for (std::int64_t i = 0; i < w; ++i)
      base.cells[static_cast<std::size_t>(j * w + i)] = toByte(grid.probability(i0_ + i, j0_ + j));
  for (int d = 1; d < depth; ++d) {
    const Level& prev = levels_[static_cast<std::size_t>(d - 1)];
    Level& level = levels_[static_cast<std::size_t>(d)];
    level.pad = (1 << d) - 1;
    level.w = w + level.pad;
    level.h = h + level.pad;
    doubleLevel(prev.cells, prev.w, prev.h, std::int64_t{1} << (d - 1), outside_, level.cells,
                level.w, level.h);
  }
}

std::size_t BranchAndBoundMatcher2D::bytes() const {
  std::size_t n = 0;
  for (const Level& l : levels_) n += l.cells.size();
  return n;
}

long BranchAndBoundMatcher2D::score(std::size_t l, const Rotated& r, int dx, int dy) const {
  ++candidates_;
  const Level& level = levels_[l];
  long sum = 0;
  const std::int64_t x = dx + level.pad, y = dy + level.pad;
  if (r.i_lo + x >= 0 && r.j_lo + y >= 0 && r.i_hi + x < level.w && r.j_hi + y < level.h) {
    // Every point inside the level: no test per point.
    const std::uint8_t* cells = level.cells.data() + y * level.w + x;
    for (const std::int64_t o : r.offsets[l]) sum += cells[o];
    return sum;
  }
  for (std::size_t k = 0; k < r.i.size(); ++k) sum += level.at(r.i[k] + dx, r.j[k] + dy, outside_);
  return sum;
}

bool BranchAndBoundMatcher2D::Leaves::excluded(const Candidate& c, double res) const {
  if (exclude == nullptr) return false;
  const double x = initial.x + c.dx * res, y = initial.y + c.dy * res;
  const double theta = initial.theta + (c.angle - m) * step;
  return std::hypot(x - exclude->centre.x, y - exclude->centre.y) <= exclude->distance &&
         std::fabs(std::remainder(theta - exclude->centre.theta, 2 * 3.14159265358979323846)) <=
             exclude->angle;
}

void BranchAndBoundMatcher2D::search(const std::vector<Rotated>& rotated, Candidate* todo,
                                     std::size_t count, int depth, int window, const Leaves& leaves,
                                     Candidate& best) const {
  std::sort(todo, todo + count,
            [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  for (std::size_t k = 0; k < count; ++k) {
    const Candidate& c = todo[k];
    if (c.score <= best.score) return;  // sorted: nothing after it can do better
    if (depth == 0) {
      if (leaves.excluded(c, res_)) continue;
      best = c;
      return;
    }
    const int half = 1 << (depth - 1);
    Candidate children[4];
    std::size_t n = 0;
    for (int oy : {0, half})
      for (int ox : {0, half}) {
        const int dx = c.dx + ox, dy = c.dy + oy;
        if (dx > window || dy > window) continue;
        children[n++] = {c.angle, dx, dy,
                         score(static_cast<std::size_t>(depth - 1),
                               rotated[static_cast<std::size_t>(c.angle)], dx, dy)};
      }
    search(rotated, children, n, depth - 1, window, leaves, best);
  }
}

std::optional<ScanMatch2D> BranchAndBoundMatcher2D::match(
    const std::vector<Eigen::Vector2f>& points, const Pose2D& initial, double linear_window,
    double angular_window, double min_score, const SearchExclusion2D* exclude) const {
  candidates_ = 0;
  if (points.empty()) return std::nullopt;
  const double step = angularSearchStep(res_, points);
  // The search's size, priced before anything is allocated: a map of very fine cells (or a
  // wide window) asks for more rotations and offsets than any budget holds.
  const double rotations = 2.0 * std::ceil(angular_window / step - 1e-9) + 1.0;
  const double offsets = 2.0 * std::floor(linear_window / res_ + 1e-9) + 1.0;
  const double top_offsets = std::ceil(offsets / static_cast<double>(1 << (levels_.size() - 1)));
  const double bytes = rotations * static_cast<double>(points.size()) *
                           (2.0 + static_cast<double>(levels_.size())) * sizeof(std::int64_t) +
                       rotations * top_offsets * top_offsets * sizeof(Candidate);
  if (!(step > 0.0) || !(rotations < 1e9) || !(offsets < 1e9) || !(bytes < 1e18)) {
    std::ostringstream msg;
    msg << "branch-and-bound search at " << res_ << " m cells: " << rotations << " rotations x "
        << offsets << " offsets per axis is beyond any memory budget";
    throw CapacityError(msg.str());
  }
  checkMemory(static_cast<std::uint64_t>(bytes), 1, "a branch-and-bound search");
  const int m = static_cast<int>((rotations - 1.0) / 2.0);
  const int window = static_cast<int>((offsets - 1.0) / 2.0);
  const double inv = 1.0 / res_;
  std::vector<Rotated> rotated(static_cast<std::size_t>(2 * m + 1));
  for (int a = -m; a <= m; ++a) {
    const double theta = initial.theta + a * step, c = std::cos(theta), s = std::sin(theta);
    Rotated& r = rotated[static_cast<std::size_t>(a + m)];
    r.i.resize(points.size());
    r.j.resize(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector2f& p = points[k];
      r.i[k] =
          static_cast<std::int64_t>(std::floor((initial.x + c * p.x() - s * p.y()) * inv)) - i0_;
      r.j[k] =
          static_cast<std::int64_t>(std::floor((initial.y + s * p.x() + c * p.y()) * inv)) - j0_;
    }
    const auto [ilo, ihi] = std::minmax_element(r.i.begin(), r.i.end());
    const auto [jlo, jhi] = std::minmax_element(r.j.begin(), r.j.end());
    r.i_lo = *ilo;
    r.i_hi = *ihi;
    r.j_lo = *jlo;
    r.j_hi = *jhi;
    r.offsets.resize(levels_.size());
    for (std::size_t l = 0; l < levels_.size(); ++l) {
      r.offsets[l].resize(points.size());
      for (std::size_t k = 0; k < points.size(); ++k)
        r.offsets[l][k] = r.j[k] * levels_[l].w + r.i[k];
    }
  }
  const int top = static_cast<int>(levels_.size()) - 1;
  const int stride = 1 << top;
  std::vector<Candidate> todo;
  for (int a = 0; a <= 2 * m; ++a)
    for (int dy = -window; dy <= window; dy += stride)
      for (int dx = -window; dx <= window; dx += stride)
        todo.push_back(
            {a, dx, dy,
             score(static_cast<std::size_t>(top), rotated[static_cast<std::size_t>(a)], dx, dy)});
  const long n = static_cast<long>(points.size());
  // The best must reach min_score: start the bound just below it.
  Candidate best{0, 0, 0, static_cast<long>(std::ceil(min_score * 255.0 * n)) - 1};
  const long floor_score = best.score;
  const Leaves leaves{initial, step, m, exclude};
  search(rotated, todo.data(), todo.size(), top, window, leaves, best);
  if (best.score <= floor_score) return std::nullopt;
  ScanMatch2D found;
  found.pose = {initial.x + best.dx * res_, initial.y + best.dy * res_,
                initial.theta + (best.angle - m) * step};
  found.score = static_cast<double>(best.score) / (255.0 * static_cast<double>(n));
  return found;
}

}  // namespace metricmap
