#pragma once
/// \file edt_kernel.h
/// \brief The exact squared Euclidean distance transform of a voxel box, separable (one exact
/// 1D pass per axis: Felzenszwalb and Huttenlocher's lower envelope of parabolas, in integer
/// arithmetic), threaded over lines, on all lines or only those a change reaches.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace metricmap::detail {

/// \brief A box of nx x ny x nz voxels, C order: voxel (i, j, k) at (i * ny + j) * nz + k.
struct EdtShape {
  std::size_t n[3] = {0, 0, 0};
  std::size_t voxels() const { return n[0] * n[1] * n[2]; }
};

/// \brief One transform's input and stores. Squared distances are in voxel units, capped at
/// `cap`: a value >= cap means "no site nearer than sqrt(cap)".
struct EdtTransform {
  /// 1 where a voxel is a site (an obstacle, or a non-obstacle for the complement).
  const std::uint8_t* site = nullptr;
  /// Per axis: space beyond the box is all sites (the box's walls count as sites at -1 and n).
  std::array<bool, 3> border{{false, false, false}};
  std::uint32_t cap = 1;
  /// After the passes along z and along z, y. May be the same array (in place, no tracking).
  std::uint32_t* pass1 = nullptr;
  std::uint32_t* pass2 = nullptr;
};

/// \brief Lines to recompute in each pass: flags over the lines of the pass along z (i, j), y
/// (i, k) and x (j, k). A pass that changes a value flags the next pass's line through it.
class EdtDirtyLines {
 public:
  explicit EdtDirtyLines(const EdtShape& shape);
  void markPass1(std::size_t i, std::size_t j) { set(0, i * ny_ + j); }
  std::atomic<std::uint8_t>* flags(int pass) { return flags_[pass].get(); }
  std::size_t count(int pass) const { return counts_[pass]; }

 private:
  void set(int pass, std::size_t line) { flags_[pass][line].store(1, std::memory_order_relaxed); }
  std::unique_ptr<std::atomic<std::uint8_t>[]> flags_[3];
  std::size_t counts_[3];
  std::size_t ny_;
};

/// \brief Writes the final pass's squared distances of line (j, k) (x varies) to the output.
/// `d2[i]` is the value of voxel (i, j, k).
class EdtSink {
 public:
  virtual ~EdtSink() = default;
  virtual void line(std::size_t j, std::size_t k, const std::uint32_t* d2) = 0;
};

/// \brief Run the three passes over every line (dirty == nullptr) or over the lines flagged
/// in `dirty` (pass 1's flags set by the caller; values compared to the stored ones, so that
/// only lines a changed value reaches are recomputed in the later passes).
/// \return lines recomputed in the three passes together
std::size_t runEdt(const EdtShape& shape, const EdtTransform& t, EdtSink& sink, unsigned threads,
                   EdtDirtyLines* dirty);

/// \brief The exact 1D pass: out[q] = min(cap, min_v (q - v)^2 + f[v]) over v in [0, n) and,
/// where `lo`/`hi`, sites of value 0 at -1 and n. `v`, `z_num`, `z_den` hold n + 2 entries.
void envelope1d(const std::uint32_t* f, std::size_t n, bool lo, bool hi, std::uint32_t cap,
                std::uint32_t* out, std::int64_t* v, std::int64_t* fv, std::int64_t* z_num,
                std::int64_t* z_den);

}  // namespace metricmap::detail
