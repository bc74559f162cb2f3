#include "metricmap/distance/edt_kernel.h"

#include <algorithm>

#include "metricmap/detail/parallel.h"

namespace metricmap::detail {
namespace {

/// The lines of one pass to run: all of them, or those flagged (flags cleared on the way).
std::vector<std::size_t> linesToRun(std::size_t count, std::atomic<std::uint8_t>* flags) {
  std::vector<std::size_t> lines;
  if (flags == nullptr) {
    lines.resize(count);
    for (std::size_t l = 0; l < count; ++l) lines[l] = l;
    return lines;
  }
  for (std::size_t l = 0; l < count; ++l) {
    if (flags[l].load(std::memory_order_relaxed) != 0) {
      lines.push_back(l);
      flags[l].store(0, std::memory_order_relaxed);
    }
  }
  return lines;
}

inline void flag(std::atomic<std::uint8_t>* flags, std::size_t line) {
  if (flags[line].load(std::memory_order_relaxed) == 0)
    flags[line].store(1, std::memory_order_relaxed);
}

/// Per-thread line buffers.
struct LineScratch {
  std::vector<std::uint32_t> in, out;
  std::vector<std::int64_t> v, fv, z_num, z_den;
  explicit LineScratch(std::size_t n)
      : in(n), out(n), v(n + 2), fv(n + 2), z_num(n + 2), z_den(n + 2) {}
  void envelope(std::size_t n, bool lo, bool hi, std::uint32_t cap) {
    envelope1d(in.data(), n, lo, hi, cap, out.data(), v.data(), fv.data(), z_num.data(),
               z_den.data());
  }
};

/// Run fn(line, scratch) over `lines`, split among threads.
template <typename Fn>
void forLines(const std::vector<std::size_t>& lines, std::size_t length, unsigned threads, Fn fn) {
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
  for (int p = 0; p < 3; ++p) flags_[p].reset(new std::atomic<std::uint8_t>[counts_[p]]());
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
  std::size_t recomputed = 0;

  // Pass 1, along z (contiguous): the 1D distance to the nearest site, two scans.
  const std::vector<std::size_t> lines1 = linesToRun(nx * ny, dirty ? dirty->flags(0) : nullptr);
  recomputed += lines1.size();
  forLines(lines1, nz, threads, [&](std::size_t line, LineScratch& s) {
    const std::size_t base = line * nz;
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
      const std::size_t i = line / ny;
      for (std::size_t q = 0; q < nz; ++q) {
        if (stored[q] != s.out[q]) flag(dirty->flags(1), i * nz + q);
      }
    }
    std::copy(s.out.begin(), s.out.begin() + static_cast<std::ptrdiff_t>(nz), stored);
  });

  // Pass 2, along y: lines (i, k), stride nz.
  const std::vector<std::size_t> lines2 = linesToRun(nx * nz, dirty ? dirty->flags(1) : nullptr);
  recomputed += lines2.size();
  forLines(lines2, ny, threads, [&](std::size_t line, LineScratch& s) {
    const std::size_t i = line / nz, k = line % nz;
    const std::size_t base = i * ny * nz + k;
    for (std::size_t j = 0; j < ny; ++j) s.in[j] = t.pass1[base + j * nz];
    s.envelope(ny, t.border[1], t.border[1], cap);
    std::uint32_t* stored = t.pass2 + base;
    for (std::size_t j = 0; j < ny; ++j) {
      if (dirty != nullptr && stored[j * nz] != s.out[j]) flag(dirty->flags(2), j * nz + k);
      stored[j * nz] = s.out[j];
    }
  });

  // Pass 3, along x: lines (j, k), stride ny * nz; the sink takes the result.
  const std::vector<std::size_t> lines3 = linesToRun(ny * nz, dirty ? dirty->flags(2) : nullptr);
  recomputed += lines3.size();
  forLines(lines3, nx, threads, [&](std::size_t line, LineScratch& s) {
    const std::size_t j = line / nz, k = line % nz;
    const std::size_t base = j * nz + k, stride = ny * nz;
    for (std::size_t i = 0; i < nx; ++i) s.in[i] = t.pass2[base + i * stride];
    s.envelope(nx, t.border[0], t.border[0], cap);
    sink.line(j, k, s.out.data());
  });
  return recomputed;
}

}  // namespace metricmap::detail
