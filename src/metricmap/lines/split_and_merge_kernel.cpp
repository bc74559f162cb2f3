#include "metricmap/lines/split_and_merge_kernel.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace metricmap {
namespace {

using Range = std::pair<std::size_t, std::size_t>;  // inclusive positions in the valid points

/// A segment under construction: one or more runs of valid points (more after a merge across
/// purged pieces or a gap).
struct Piece {
  std::vector<Range> ranges;
  std::size_t first() const { return ranges.front().first; }
  std::size_t last() const { return ranges.back().second; }
  std::size_t points() const {
    std::size_t n = 0;
    for (const Range& r : ranges) n += r.second - r.first + 1;
    return n;
  }
};

class Segmenter {
 public:
  Segmenter(const std::vector<Eigen::Vector2d>& xy, const std::vector<int>& beams,
            const SplitAndMergeParams& params, const SplitAndMergeStep* step)
      : xy_(xy), beams_(beams), params_(params), step_(step) {}

  LineSegment chord(const Piece& p) const {
    LineSegment s;
    s.start = xy_[p.first()];
    s.end = xy_[p.last()];
    s.first_index = beams_[p.first()];
    s.last_index = beams_[p.last()];
    s.points = p.points();
    return s;
  }

  Eigen::Matrix2d covariance(std::size_t i) const {
    return polarPointCovariance(xy_[i].norm(), std::atan2(xy_[i].y(), xy_[i].x()),
                                params_.range_sigma, params_.bearing_sigma);
  }

  /// Split score of point i against the chord (unit normal u, through start, length > 0 or
  /// u = 0 for a degenerate chord): distance, or d^2 / var(d) for the chi-square test.
  double score(const Eigen::Vector2d& u, const Eigen::Vector2d& start, std::size_t i) const {
    const double d = u.isZero() ? (xy_[i] - start).norm() : std::fabs(u.dot(xy_[i] - start));
    if (!params_.chi2_split) return d;
    const Eigen::Matrix2d c = covariance(i);
    const double var = u.isZero() ? c.trace() / 2.0 : u.dot(c * u);
    if (var <= 0.0) return d > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    return d * d / var;
  }

  double threshold() const {
    return params_.chi2_split ? params_.chi2_threshold : params_.distance_threshold;
  }

  std::vector<Piece> gaps() const {
    std::vector<Piece> chunks;
    std::size_t begin = 0;
    for (std::size_t i = 1; i <= xy_.size(); ++i) {
      const bool cut = i == xy_.size() ||
                       (params_.max_gap > 0.0 && (xy_[i] - xy_[i - 1]).norm() > params_.max_gap);
      if (cut) {
        chunks.push_back(Piece{{{begin, i - 1}}});
        begin = i;
      }
    }
    return chunks;
  }

  /// Iterative split with an explicit stack; pieces come out in scan order and every point
  /// belongs to exactly one piece (the farthest point closes the first half).
  std::vector<Piece> split(const std::vector<Piece>& chunks) const {
    std::vector<Piece> out;
    for (const Piece& chunk : chunks) {
      std::vector<Range> stack{chunk.ranges.front()};
      while (!stack.empty()) {
        const Range r = stack.back();
        stack.pop_back();
        std::size_t best = r.first;
        double best_score = -1.0;
        if (r.second - r.first >= 2) {
          const LineSegment line = chord(Piece{{r}});
          // A chord shorter than d_th (a closed 360-degree scan starts and ends at nearly the
          // same point) has no meaningful direction: measure from its start point instead.
          const Eigen::Vector2d u =
              line.length() < params_.distance_threshold ? Eigen::Vector2d::Zero() : line.normal();
          for (std::size_t i = r.first + 1; i < r.second; ++i) {
            const double sc = score(u, line.start, i);
            if (sc > best_score) {
              best_score = sc;
              best = i;
            }
          }
        }
        if (best_score > threshold()) {
          stack.push_back({best + 1, r.second});
          stack.push_back({r.first, best});
          notify("split", out, stack);
        } else {
          out.push_back(Piece{{r}});
        }
      }
    }
    return out;
  }

  /// Merge neighbours whose chords (first to last point) differ by less than the angle
  /// threshold, to a fixpoint: a merged piece is compared again with the piece before it, so
  /// that afterwards no two neighbours differ by less than the threshold.
  std::vector<Piece> merge(const std::vector<Piece>& pieces) const {
    if (pieces.empty() || params_.angle_threshold <= 0.0) return pieces;
    std::vector<Piece> out;
    Piece current = pieces.front();
    auto joins = [&](const Piece& a, const Piece& b) {
      return std::fabs(chord(a).angleTo(chord(b))) < params_.angle_threshold;
    };
    for (std::size_t i = 1; i < pieces.size(); ++i) {
      const Piece& next = pieces[i];
      if (!joins(current, next)) {
        out.push_back(std::move(current));
        current = next;
        continue;
      }
      current.ranges.insert(current.ranges.end(), next.ranges.begin(), next.ranges.end());
      notifyMerge(out, current, pieces, i);
      while (!out.empty() && joins(out.back(), current)) {
        Piece joined = std::move(out.back());
        out.pop_back();
        joined.ranges.insert(joined.ranges.end(), current.ranges.begin(), current.ranges.end());
        current = std::move(joined);
        notifyMerge(out, current, pieces, i);
      }
    }
    out.push_back(current);
    return out;
  }

  std::vector<Piece> purge(const std::vector<Piece>& pieces) const {
    std::vector<Piece> out;
    for (const Piece& p : pieces) {
      if (p.points() >= params_.min_points && chord(p).length() >= params_.min_length) {
        out.push_back(p);
      }
    }
    if (step_ != nullptr && out.size() != pieces.size()) (*step_)("purge", segments(out));
    return out;
  }

  std::vector<LineSegment> segments(const std::vector<Piece>& pieces, bool with_fit = false) const {
    std::vector<LineSegment> out;
    out.reserve(pieces.size());
    for (const Piece& p : pieces) {
      LineSegment s = chord(p);
      if (with_fit) {
        std::vector<Eigen::Vector2d> pts;
        std::vector<Eigen::Matrix2d> covs;
        for (const Range& r : p.ranges) {
          for (std::size_t i = r.first; i <= r.second; ++i) {
            pts.push_back(xy_[i]);
            covs.push_back(covariance(i));
          }
        }
        s.fit = fitLine(pts, covs);
      }
      out.push_back(s);
    }
    return out;
  }

  std::vector<int> memberBeams(const Piece& p) const {
    std::vector<int> b;
    for (const Range& r : p.ranges) {
      for (std::size_t i = r.first; i <= r.second; ++i) b.push_back(beams_[i]);
    }
    return b;
  }

 private:
  void notifyMerge(const std::vector<Piece>& done, const Piece& current,
                   const std::vector<Piece>& pieces, std::size_t i) const {
    if (step_ == nullptr) return;
    std::vector<Piece> now = done;
    now.push_back(current);
    now.insert(now.end(), pieces.begin() + static_cast<std::ptrdiff_t>(i) + 1, pieces.end());
    (*step_)("merge", segments(now));
  }

  void notify(const char* what, const std::vector<Piece>& done,
              const std::vector<Range>& todo) const {
    if (step_ == nullptr) return;
    std::vector<Piece> now = done;
    for (auto it = todo.rbegin(); it != todo.rend(); ++it) now.push_back(Piece{{*it}});
    (*step_)(what, segments(now));
  }

  const std::vector<Eigen::Vector2d>& xy_;
  const std::vector<int>& beams_;
  const SplitAndMergeParams& params_;
  const SplitAndMergeStep* step_;
};

}  // namespace

void validateSplitAndMergeParams(const SplitAndMergeParams& p) {
  auto bad = [](const char* name, double v, const char* rule) {
    std::ostringstream os;
    os << name << " must be " << rule << ", got " << v;
    throw std::invalid_argument(os.str());
  };
  if (!std::isfinite(p.distance_threshold) || !(p.distance_threshold > 0.0)) {
    bad("distance threshold", p.distance_threshold, "a finite number > 0");
  }
  if (!std::isfinite(p.angle_threshold) || p.angle_threshold < 0.0) {
    bad("angle threshold", p.angle_threshold, "a finite number >= 0");
  }
  if (!std::isfinite(p.min_length) || p.min_length < 0.0) {
    bad("minimum length", p.min_length, "a finite number >= 0");
  }
  if (!std::isfinite(p.max_gap) || p.max_gap < 0.0)
    bad("maximum gap", p.max_gap, "a finite number >= 0");
  if (!std::isfinite(p.chi2_threshold) || !(p.chi2_threshold > 0.0)) {
    bad("chi-square threshold", p.chi2_threshold, "a finite number > 0");
  }
  if (!std::isfinite(p.range_sigma) || p.range_sigma < 0.0) {
    bad("range sigma", p.range_sigma, "a finite number >= 0");
  }
  if (!std::isfinite(p.bearing_sigma) || p.bearing_sigma < 0.0) {
    bad("bearing sigma", p.bearing_sigma, "a finite number >= 0");
  }
}

std::vector<LineSegment> splitAndMerge(const std::vector<Eigen::Vector2d>& xy,
                                       const std::vector<int>& beams,
                                       const SplitAndMergeParams& params,
                                       const SplitAndMergeStep* step,
                                       std::vector<std::vector<int>>* members) {
  validateSplitAndMergeParams(params);
  if (xy.size() != beams.size())
    throw std::invalid_argument("splitAndMerge: xy and beams differ in size");
  if (members != nullptr) members->clear();
  if (xy.empty()) return {};
  const Segmenter seg(xy, beams, params, step);
  std::vector<Piece> chunks = seg.gaps();
  if (step != nullptr && chunks.size() > 1) (*step)("gap", seg.segments(chunks));
  std::vector<Piece> pieces = seg.split(chunks);
  if (params.purge_order == PurgeOrder::BeforeMerge) pieces = seg.purge(pieces);
  pieces = seg.merge(pieces);
  if (params.purge_order == PurgeOrder::AfterMerge) pieces = seg.purge(pieces);
  if (members != nullptr) {
    for (const Piece& p : pieces) members->push_back(seg.memberBeams(p));
  }
  return seg.segments(pieces, true);
}

}  // namespace metricmap
