#include "metricmap/slam/branch_and_bound_2d.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"

namespace metricmap {
namespace {

std::uint8_t toByte(float p) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(p, 0.0f, 1.0f) * 255.0f));
}

/// out[k] = max(in[k - width + 1 .. k]) for k in [0, n + width - 1), `pad` outside in.
void slidingMax(const std::uint8_t* in, std::ptrdiff_t in_stride, std::int64_t n, int width,
                std::uint8_t pad, std::uint8_t* out, std::ptrdiff_t out_stride) {
  std::deque<std::pair<std::int64_t, std::uint8_t>> window;  // decreasing values
  auto value = [&](std::int64_t k) { return k >= 0 && k < n ? in[k * in_stride] : pad; };
  for (std::int64_t k = 0; k < n + width - 1; ++k) {
    const std::uint8_t v = value(k);
    while (!window.empty() && window.back().second <= v) window.pop_back();
    window.emplace_back(k, v);
    while (window.front().first <= k - width) window.pop_front();
    // the padding before index 0 is `pad`, which can exceed every value seen so far
    std::uint8_t m = window.front().second;
    if (k - width + 1 < 0 && pad > m) m = pad;
    out[k * out_stride] = m;
  }
}

}  // namespace

BranchAndBoundMatcher2D::BranchAndBoundMatcher2D(const MatchGrid& grid, int depth)
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
  checkMemory(total, 1, "the loop-closure grids of a submap");
  std::vector<std::uint8_t> base(static_cast<std::size_t>(w * h));
  for (std::int64_t j = 0; j < h; ++j)
    for (std::int64_t i = 0; i < w; ++i)
      base[static_cast<std::size_t>(j * w + i)] = toByte(grid.probability(i0_ + i, j0_ + j));
  levels_.resize(static_cast<std::size_t>(depth));
  for (int d = 0; d < depth; ++d) {
    const int width = 1 << d;
    Level& level = levels_[static_cast<std::size_t>(d)];
    level.pad = width - 1;
    level.w = w + level.pad;
    level.h = h + level.pad;
    std::vector<std::uint8_t> rows(static_cast<std::size_t>(level.w * h));
    for (std::int64_t j = 0; j < h; ++j)
      slidingMax(base.data() + j * w, 1, w, width, outside_, rows.data() + j * level.w, 1);
    level.cells.resize(static_cast<std::size_t>(level.w * level.h));
    for (std::int64_t i = 0; i < level.w; ++i)
      slidingMax(rows.data() + i, level.w, h, width, outside_, level.cells.data() + i, level.w);
  }
}

std::size_t BranchAndBoundMatcher2D::bytes() const {
  std::size_t n = 0;
  for (const Level& l : levels_) n += l.cells.size();
  return n;
}

long BranchAndBoundMatcher2D::score(const Level& level, const std::vector<std::int64_t>& ci,
                                    const std::vector<std::int64_t>& cj, int dx, int dy) const {
  ++candidates_;
  long sum = 0;
  for (std::size_t k = 0; k < ci.size(); ++k) sum += level.at(ci[k] + dx, cj[k] + dy, outside_);
  return sum;
}

void BranchAndBoundMatcher2D::search(const std::vector<std::vector<std::int64_t>>& ci,
                                     const std::vector<std::vector<std::int64_t>>& cj,
                                     std::vector<Candidate>& todo, int depth, int window,
                                     Candidate& best) const {
  std::sort(todo.begin(), todo.end(),
            [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  for (const Candidate& c : todo) {
    if (c.score <= best.score) return;  // sorted: nothing after it can do better
    if (depth == 0) {
      best = c;
      return;
    }
    const int half = 1 << (depth - 1);
    const Level& level = levels_[static_cast<std::size_t>(depth - 1)];
    std::vector<Candidate> children;
    children.reserve(4);
    for (int oy : {0, half})
      for (int ox : {0, half}) {
        const int dx = c.dx + ox, dy = c.dy + oy;
        if (dx > window || dy > window) continue;
        children.push_back({c.angle, dx, dy,
                            score(level, ci[static_cast<std::size_t>(c.angle)],
                                  cj[static_cast<std::size_t>(c.angle)], dx, dy)});
      }
    search(ci, cj, children, depth - 1, window, best);
  }
}

std::optional<ScanMatch2D> BranchAndBoundMatcher2D::match(
    const std::vector<Eigen::Vector2f>& points, const Pose2D& initial, double linear_window,
    double angular_window, double min_score) const {
  candidates_ = 0;
  if (points.empty()) return std::nullopt;
  const double step = angularSearchStep(res_, points);
  const int m = static_cast<int>(std::ceil(angular_window / step - 1e-9));
  const int window = static_cast<int>(std::floor(linear_window / res_ + 1e-9));
  const double inv = 1.0 / res_;
  std::vector<std::vector<std::int64_t>> ci(static_cast<std::size_t>(2 * m + 1)),
      cj(static_cast<std::size_t>(2 * m + 1));
  for (int a = -m; a <= m; ++a) {
    const double theta = initial.theta + a * step, c = std::cos(theta), s = std::sin(theta);
    auto& is = ci[static_cast<std::size_t>(a + m)];
    auto& js = cj[static_cast<std::size_t>(a + m)];
    is.resize(points.size());
    js.resize(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector2f& p = points[k];
      is[k] =
          static_cast<std::int64_t>(std::floor((initial.x + c * p.x() - s * p.y()) * inv)) - i0_;
      js[k] =
          static_cast<std::int64_t>(std::floor((initial.y + s * p.x() + c * p.y()) * inv)) - j0_;
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
             score(levels_[static_cast<std::size_t>(top)], ci[static_cast<std::size_t>(a)],
                   cj[static_cast<std::size_t>(a)], dx, dy)});
  const long n = static_cast<long>(points.size());
  // The best must reach min_score: start the bound just below it.
  Candidate best{0, 0, 0, static_cast<long>(std::ceil(min_score * 255.0 * n)) - 1};
  const long floor_score = best.score;
  search(ci, cj, todo, top, window, best);
  if (best.score <= floor_score) return std::nullopt;
  ScanMatch2D found;
  found.pose = {initial.x + best.dx * res_, initial.y + best.dy * res_,
                initial.theta + (best.angle - m) * step};
  found.score = static_cast<double>(best.score) / (255.0 * static_cast<double>(n));
  return found;
}

}  // namespace metricmap
