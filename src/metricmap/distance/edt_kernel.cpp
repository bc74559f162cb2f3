#include "metricmap/distance/edt_kernel.h"

#include <algorithm>
#include <cmath>

#include "metricmap/detail/parallel.h"

namespace metricmap::detail {
namespace {

/// A line of a pass to run and the chunks of it that changed (all for a full run).
struct DirtyLine {
  std::size_t line;
  std::uint64_t mask;
};

/// The lines of one pass to run: all of them, or those marked (marks cleared on the way).
std::vector<DirtyLine> linesToRun(std::size_t count, std::atomic<std::uint64_t>* masks) {
  std::vector<DirtyLine> lines;
  if (masks == nullptr) {
    lines.resize(count);
    for (std::size_t l = 0; l < count; ++l) lines[l] = {l, ~std::uint64_t{0}};
    return lines;
  }
  for (std::size_t l = 0; l < count; ++l) {
    const std::uint64_t m = masks[l].load(std::memory_order_relaxed);
    if (m != 0) {
      lines.push_back({l, m});
      masks[l].store(0, std::memory_order_relaxed);
    }
  }
  return lines;
}

/// Smallest r with r * r >= cap: a value at v changes no result farther than r - 1 from v.
std::size_t reachOf(std::uint32_t cap) {
  std::size_t r = static_cast<std::size_t>(std::sqrt(static_cast<double>(cap)));
  while (r * r < cap) ++r;
  while (r > 0 && (r - 1) * (r - 1) >= cap) --r;
  return r;
}

/// The spans [lo, hi] of a line of n voxels to recompute: the changed chunks of `mask` (chunks
/// of `chunk` voxels), widened by `reach` on each side, overlapping or near ones merged.
template <typename Fn>
void forSpans(std::uint64_t mask, std::size_t n, std::size_t chunk, std::size_t reach, Fn fn) {
  if (mask == ~std::uint64_t{0}) return fn(std::size_t{0}, n - 1);
  bool open = false;
  std::size_t span_lo = 0, span_hi = 0;
  for (std::size_t c = 0; c < 64 && c * chunk < n; ++c) {
    if (((mask >> c) & 1) == 0) continue;
    const std::size_t p_lo = c * chunk, p_hi = std::min(n, (c + 1) * chunk) - 1;
    const std::size_t lo = p_lo > reach ? p_lo - reach : 0, hi = std::min(n - 1, p_hi + reach);
    if (open && lo <= span_hi + 2 * reach + 1) {
      span_hi = hi;  // nearer than the inputs two spans would read twice: one span
      continue;
    }
    if (open) fn(span_lo, span_hi);
    open = true;
    span_lo = lo;
    span_hi = hi;
  }
  if (open) fn(span_lo, span_hi);
}

/// Per-thread line buffers.
struct LineScratch {
  std::vector<std::uint32_t> in, out;
  std::vector<std::int64_t> v, fv, z_num, z_den;
  explicit LineScratch(std::size_t n)
      : in(n), out(n), v(n + 2), fv(n + 2), z_num(n + 2), z_den(n + 2) {}
  /// The exact values of voxels [lo, hi] of a line of n: the envelope of the inputs within
  /// `reach` of the span (read by `input(q)`), the walls where those inputs reach them.
  /// \return the offset in out[] of voxel lo
  template <typename Input>
  std::size_t span(std::size_t n, std::size_t lo, std::size_t hi, std::size_t reach, bool border,
                   std::uint32_t cap, Input input) {
    const std::size_t in_lo = lo > reach ? lo - reach : 0;
    const std::size_t in_hi = std::min(n - 1, hi + reach);
    for (std::size_t q = in_lo; q <= in_hi; ++q) in[q - in_lo] = input(q);
    envelope1d(in.data(), in_hi - in_lo + 1, border && in_lo == 0, border && in_hi == n - 1, cap,
               out.data(), v.data(), fv.data(), z_num.data(), z_den.data());
    return lo - in_lo;
  }
};

/// Run fn(line, scratch) over `lines`, split among threads.
template <typename Fn>
void forLines(const std::vector<DirtyLine>& lines, std::size_t length, unsigned threads, Fn fn) {
  const unsigned used = resolveThreads(threads, lines.size() * std::max<std::size_t>(1, length),
                                       std::size_t{1} << 15);
  parallelRun(used, [&](unsigned t) {
    const auto [begin, end] = chunkOf(lines.size(), used, t);
    LineScratch scratch(length);
    for (std::size_t l = begin; l < end; ++l) fn(lines[l], scratch);
  });
}

}  // namespace

EdtDirtyLines::EdtDirtyLines(const EdtShape& shape) : ny_(shape.n[1]) {
  counts_[0] = shape.n[0] * shape.n[1];
  counts_[1] = shape.n[0] * shape.n[2];
  counts_[2] = shape.n[1] * shape.n[2];
  const std::size_t length[3] = {shape.n[2], shape.n[1], shape.n[0]};  // along z, y, x
  for (int p = 0; p < 3; ++p) {
    chunk_[p] = std::max<std::size_t>(1, (length[p] + 63) / 64);
    masks_[p].reset(new std::atomic<std::uint64_t>[counts_[p]]());
  }
}

void envelope1d(const std::uint32_t* f, std::size_t n, bool lo, bool hi, std::uint32_t cap,
                std::uint32_t* out, std::int64_t* v, std::int64_t* fv, std::int64_t* z_num,
                std::int64_t* z_den) {
  // Lower envelope of the parabolas (x - q)^2 + f[q] of the sites with f[q] < cap (the others
  // never give a value below cap). Boundary k between parabolas k - 1 and k lies at
  // z_num[k] / z_den[k] (z_den > 0); comparisons are exact in 64-bit integers.
  std::ptrdiff_t k = -1;
  const auto add = [&](std::int64_t q, std::int64_t fq) {
    while (k >= 0) {
      const std::int64_t num = (fq + q * q) - (fv[k] + v[k] * v[k]);
      const std::int64_t den = 2 * (q - v[k]);
      if (k > 0 && num * z_den[k] <= z_num[k] * den) {
        --k;  // parabola k is nowhere lowest
        continue;
      }
      ++k;
      v[k] = q;
      fv[k] = fq;
      z_num[k] = num;
      z_den[k] = den;
      return;
    }
    k = 0;
    v[0] = q;
    fv[0] = fq;
  };
  if (lo) add(-1, 0);
  for (std::size_t q = 0; q < n; ++q) {
    if (f[q] < cap) add(static_cast<std::int64_t>(q), f[q]);
  }
  if (hi) add(static_cast<std::int64_t>(n), 0);
  if (k < 0) {
    std::fill(out, out + n, cap);
    return;
  }
  std::ptrdiff_t e = 0;
  for (std::size_t qi = 0; qi < n; ++qi) {
    const auto q = static_cast<std::int64_t>(qi);
    while (e < k && z_num[e + 1] < q * z_den[e + 1]) ++e;
    const std::int64_t d = (q - v[e]) * (q - v[e]) + fv[e];
    out[qi] = d < static_cast<std::int64_t>(cap) ? static_cast<std::uint32_t>(d) : cap;
  }
}

std::size_t runEdt(const EdtShape& shape, const EdtTransform& t, EdtSink& sink, unsigned threads,
                   EdtDirtyLines* dirty) {
  const std::size_t nx = shape.n[0], ny = shape.n[1], nz = shape.n[2];
  const std::uint32_t cap = t.cap;
  const std::size_t reach = reachOf(cap);
  std::size_t recomputed = 0;

  // Pass 1, along z (contiguous): the 1D distance to the nearest site, two scans.
  const std::vector<DirtyLine> lines1 = linesToRun(nx * ny, dirty ? dirty->masks(0) : nullptr);
  recomputed += lines1.size();
  forLines(lines1, nz, threads, [&](const DirtyLine& dl, LineScratch& s) {
    const std::size_t base = dl.line * nz;
    const std::uint8_t* site = t.site + base;
    const auto n = static_cast<std::int64_t>(nz);
    constexpr std::int64_t kNone = -(std::int64_t{1} << 40);
    std::int64_t last = t.border[2] ? -1 : kNone;
    for (std::int64_t q = 0; q < n; ++q) {
      if (site[q]) last = q;
      const std::int64_t d = q - last;
      s.out[q] = last == kNone || d * d >= cap ? cap : static_cast<std::uint32_t>(d * d);
    }
    last = t.border[2] ? n : -kNone;
    for (std::int64_t q = n - 1; q >= 0; --q) {
      if (site[q]) last = q;
      const std::int64_t d = last - q;
      if (last != -kNone && d * d < s.out[q]) s.out[q] = static_cast<std::uint32_t>(d * d);
    }
    std::uint32_t* stored = t.pass1 + base;
    if (dirty != nullptr) {
      const std::size_t i = dl.line / ny, j = dl.line % ny;
      for (std::size_t q = 0; q < nz; ++q) {
        if (stored[q] != s.out[q]) dirty->mark(1, i * nz + q, j);
      }
    }
    std::copy(s.out.begin(), s.out.begin() + static_cast<std::ptrdiff_t>(nz), stored);
  });

  // Pass 2, along y: lines (i, k), stride nz.
  const std::vector<DirtyLine> lines2 = linesToRun(nx * nz, dirty ? dirty->masks(1) : nullptr);
  recomputed += lines2.size();
  const std::size_t chunk2 = dirty ? dirty->chunk(1) : ny;
  forLines(lines2, ny, threads, [&](const DirtyLine& dl, LineScratch& s) {
    const std::size_t i = dl.line / nz, k = dl.line % nz;
    const std::size_t base = i * ny * nz + k;
    const std::uint32_t* line_in = t.pass1 + base;
    std::uint32_t* stored = t.pass2 + base;
    forSpans(dl.mask, ny, chunk2, reach, [&](std::size_t lo, std::size_t hi) {
      const std::size_t at = s.span(ny, lo, hi, reach, t.border[1], cap,
                                    [&](std::size_t q) { return line_in[q * nz]; });
      for (std::size_t j = lo; j <= hi; ++j) {
        const std::uint32_t v = s.out[at + j - lo];
        if (dirty != nullptr && stored[j * nz] != v) dirty->mark(2, j * nz + k, i);
        stored[j * nz] = v;
      }
    });
  });

  // Pass 3, along x: lines (j, k), stride ny * nz; the sink takes the result.
  const std::vector<DirtyLine> lines3 = linesToRun(ny * nz, dirty ? dirty->masks(2) : nullptr);
  recomputed += lines3.size();
  const std::size_t chunk3 = dirty ? dirty->chunk(2) : nx;
  forLines(lines3, nx, threads, [&](const DirtyLine& dl, LineScratch& s) {
    const std::size_t j = dl.line / nz, k = dl.line % nz;
    const std::size_t base = j * nz + k, stride = ny * nz;
    const std::uint32_t* line_in = t.pass2 + base;
    forSpans(dl.mask, nx, chunk3, reach, [&](std::size_t lo, std::size_t hi) {
      const std::size_t at = s.span(nx, lo, hi, reach, t.border[0], cap,
                                    [&](std::size_t q) { return line_in[q * stride]; });
      sink.line(j, k, lo, hi + 1, s.out.data() + at);
    });
  });
  return recomputed;
}

}  // namespace metricmap::detail
