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

/// \brief What to recompute in each pass, per line of the pass along z (i, j), y (i, k) and
/// x (j, k): a mask of the chunks (of ceil(n / 64) voxels) holding a value that changed. A pass
/// recomputes, on a dirty line, only the voxels a changed value can reach (within sqrt(cap)),
/// compares them with the stored ones and marks the next pass's lines through each change.
class EdtDirtyLines {
 public:
  explicit EdtDirtyLines(const EdtShape& shape);
  /// The whole z-line (i, j) changed (its sites did).
  void markPass1(std::size_t i, std::size_t j) {
    masks_[0][i * ny_ + j].store(~std::uint64_t{0}, std::memory_order_relaxed);
  }
  /// Voxel q of line `line` of pass `pass` (0, 1, 2) holds a changed input.
  void mark(int pass, std::size_t line, std::size_t q) {
    std::atomic<std::uint64_t>& m = masks_[pass][line];
    const std::uint64_t bit = std::uint64_t{1} << (q / chunk_[pass]);
    if ((m.load(std::memory_order_relaxed) & bit) == 0) m.fetch_or(bit, std::memory_order_relaxed);
  }
  std::atomic<std::uint64_t>* masks(int pass) { return masks_[pass].get(); }
  std::size_t count(int pass) const { return counts_[pass]; }
  std::size_t chunk(int pass) const { return chunk_[pass]; }

 private:
  std::unique_ptr<std::atomic<std::uint64_t>[]> masks_[3];
  std::size_t counts_[3], chunk_[3];
  std::size_t ny_;
};

/// \brief Writes the final pass's squared distances of voxels i0..i1-1 of line (j, k) (x
/// varies) to the output. `d2[i - i0]` is the value of voxel (i, j, k).
class EdtSink {
 public:
  virtual ~EdtSink() = default;
  virtual void line(std::size_t j, std::size_t k, std::size_t i0, std::size_t i1,
                    const std::uint32_t* d2) = 0;
};

/// \brief Run the three passes over every line (dirty == nullptr) or over what `dirty` marks
/// (pass 1's lines marked by the caller; values compared to the stored ones, so that only the
/// spans a changed value reaches are recomputed in the later passes).
/// \return lines recomputed (wholly or in part) in the three passes together
std::size_t runEdt(const EdtShape& shape, const EdtTransform& t, EdtSink& sink, unsigned threads,
                   EdtDirtyLines* dirty);

/// \brief The exact 1D pass: out[q] = min(cap, min_v (q - v)^2 + f[v]) over v in [0, n) and,
/// where `lo`/`hi`, sites of value 0 at -1 and n. `v`, `z_num`, `z_den` hold n + 2 entries.
void envelope1d(const std::uint32_t* f, std::size_t n, bool lo, bool hi, std::uint32_t cap,
                std::uint32_t* out, std::int64_t* v, std::int64_t* fv, std::int64_t* z_num,
                std::int64_t* z_den);

}  // namespace metricmap::detail
