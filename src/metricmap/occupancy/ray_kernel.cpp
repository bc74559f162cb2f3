#include "metricmap/occupancy/ray_kernel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

// The SIMD walks need SSE2 and 64-bit lanes moved to general registers (x86-64); elsewhere only
// the portable walk is compiled.
#if defined(__SSE2__) && defined(__x86_64__)
#define METRICMAP_RAY_SIMD 1
#include <immintrin.h>
#else
#define METRICMAP_RAY_SIMD 0
#endif

#include "metricmap/common/memory_budget.h"
#include "metricmap/detail/fast_floor.h"
#include "metricmap/detail/voxel_key.h"
#include "metricmap/exceptions.h"

namespace metricmap::detail {

void BlockHashIndex::clear() {
  std::fill(keys_.begin(), keys_.end(), kEmpty);
  size_ = 0;
}

void BlockHashIndex::grow() {
  const std::size_t capacity = keys_.empty() ? 1024 : keys_.size() * 2;
  std::vector<std::uint64_t> old_keys(capacity, kEmpty);
  std::vector<std::uint32_t> old_values(capacity);
  old_keys.swap(keys_);
  old_values.swap(values_);
  mask_ = capacity - 1;
  shift_ = 64 - __builtin_ctzll(capacity);
  size_ = 0;
  for (std::size_t i = 0; i < old_keys.size(); ++i) {
    if (old_keys[i] == kEmpty) continue;
    std::size_t s = slot(old_keys[i]);
    while (keys_[s] != kEmpty) s = (s + 1) & mask_;
    keys_[s] = old_keys[i];
    values_[s] = old_values[i];
    ++size_;
  }
}

namespace {

std::atomic<RayPath> g_ray_path{RayPath::Simd};

}  // namespace

RayPath rayPath() {
#if METRICMAP_RAY_SIMD
  return g_ray_path.load(std::memory_order_relaxed);
#else
  return RayPath::Portable;
#endif
}

void setRayPathForTesting(RayPath path) { g_ray_path.store(path, std::memory_order_relaxed); }

namespace {

/// Marks voxels into the scan's blocks; remembers the last block touched.
class Marker {
 public:
  Marker(ScanUpdate& out, std::size_t max_blocks, double resolution)
      : out_(out), max_blocks_(max_blocks), resolution_(resolution) {}

  std::uint64_t* freeWords(std::int64_t bx, std::int64_t by, std::int64_t bz) {
    return blockAt(bx, by, bz).free;
  }
  ScanBlock& blockAt(std::int64_t bx, std::int64_t by, std::int64_t bz) {
    if (bx != bx_ || by != by_ || bz != bz_) select(bx, by, bz);
    return *block_;
  }
  void markFree(std::int64_t x, std::int64_t y, std::int64_t z) {
    std::uint64_t* w = freeWords(x >> kBlockShift, y >> kBlockShift, z >> kBlockShift);
    const int i = voxelInBlock(x, y, z);
    w[i >> 6] |= std::uint64_t{1} << (i & 63);
  }
  void markHit(std::int64_t x, std::int64_t y, std::int64_t z) {
    freeWords(x >> kBlockShift, y >> kBlockShift, z >> kBlockShift);
    const int i = voxelInBlock(x, y, z);
    block_->hit[i >> 6] |= std::uint64_t{1} << (i & 63);
  }

 private:
  void select(std::int64_t bx, std::int64_t by, std::int64_t bz) {
    const std::uint64_t key = packVoxelKey(bx, by, bz);
    bool inserted = false;
    const auto next = static_cast<std::uint32_t>(out_.blocks.size());
    const std::uint32_t index = out_.index.findOrInsert(key, next, inserted);
    if (inserted) {
      if (out_.blocks.size() >= max_blocks_) tooManyBlocks();
      out_.blocks.emplace_back();
      ScanBlock& b = out_.blocks.back();
      std::memset(b.free, 0, sizeof(b.free));
      std::memset(b.hit, 0, sizeof(b.hit));
      b.key = key;
    }
    block_ = &out_.blocks[index];
    bx_ = bx;
    by_ = by;
    bz_ = bz;
  }

  [[noreturn]] void tooManyBlocks() const {
    std::ostringstream msg;
    msg << "the scan's beams cross more than " << max_blocks_ << " blocks of 8^3 voxels at "
        << "resolution " << resolution_ << " m: the map would need more than the memory budget "
        << "of " << (memoryBudget() >> 20) << " MiB (--max-memory; a coarser --resolution or a "
        << "shorter --max-range needs less)";
    throw CapacityError(msg.str());
  }

  ScanUpdate& out_;
  std::size_t max_blocks_;
  double resolution_;
  ScanBlock* block_ = nullptr;
  std::int64_t bx_ = std::numeric_limits<std::int64_t>::min(), by_ = 0, bz_ = 0;
};

struct Key3 {
  std::int64_t v[3];
};

[[noreturn]] void outsideKeySpace(const float p[3], double resolution) {
  std::ostringstream msg;
  msg << "point (" << p[0] << ", " << p[1] << ", " << p[2] << ") is outside the voxel key space ("
      << "+-" << static_cast<double>(kVoxelKeyLimit) * resolution << " m at resolution "
      << resolution << " m)";
  throw CapacityError(msg.str());
}

/// OctoMap's coordToKey: floor(coordinate * (1 / resolution)) in double.
bool keyOf(const float p[3], double inv_res, Key3& key) {
  for (int i = 0; i < 3; ++i) {
    const double s = inv_res * static_cast<double>(p[i]);
    if (!(s >= -static_cast<double>(kVoxelKeyLimit) && s < static_cast<double>(kVoxelKeyLimit)))
      return false;
    key.v[i] = floorToInt(s);
  }
  return true;
}

/// One beam being walked: OctoMap's computeRayKeys state (Amanatides & Woo in double from
/// float coordinates): crossing parameters t, their steps dt, the length; keys, steps, end key.
struct Beam {
  double t[3], dt[3], length;
  std::int64_t k[3], step[3];
  std::int32_t ke[3];
};

/// OctoMap's initialisation of computeRayKeys for origin o, end e (keys differ).
void startBeam(const float o[3], const float e[3], const Key3& ko, const std::int32_t ke[3],
               double res, Beam& b) {
  float dir[3] = {e[0] - o[0], e[1] - o[1], e[2] - o[2]};
  const float length = static_cast<float>(
      std::sqrt(static_cast<double>(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2])));
  dir[0] /= length;
  dir[1] /= length;
  dir[2] /= length;
  for (int i = 0; i < 3; ++i) {
    b.k[i] = ko.v[i];
    b.ke[i] = ke[i];
    b.step[i] = dir[i] > 0.0f ? 1 : (dir[i] < 0.0f ? -1 : 0);
    double t_max = std::numeric_limits<double>::max();
    double t_delta = std::numeric_limits<double>::max();
    if (b.step[i] != 0) {
      double border = (static_cast<double>(ko.v[i]) + 0.5) * res;
      border += static_cast<float>(static_cast<double>(b.step[i]) * res * 0.5);
      t_max = (border - static_cast<double>(o[i])) / static_cast<double>(dir[i]);
      t_delta = res / static_cast<double>(std::fabs(dir[i]));
    }
    b.t[i] = t_max;
    b.dt[i] = t_delta;
  }
  b.length = static_cast<double>(length);
}

/// A bit per voxel of the scan's box, x fastest, rows padded to 64 bits: a step moves the bit
/// index by a fixed stride per axis, so marking costs no multiplication.
struct LinearBits {
  std::uint64_t* bits;
  std::int64_t x0, y0, z0, row_bits, slice_bits;
  std::int64_t index(std::int64_t x, std::int64_t y, std::int64_t z) const {
    return (x - x0) + (y - y0) * row_bits + (z - z0) * slice_bits;
  }
  void set(std::int64_t i) { bits[i >> 6] |= std::uint64_t{1} << (i & 63); }
  void set(std::int64_t x, std::int64_t y, std::int64_t z) { set(index(x, y, z)); }
};

/// A bit per voxel of the scan's box in 8^3-voxel blocks of 512 bits (one cache line each),
/// blocks x fastest; inside a block a voxel's bit is ScanBlock's (word z & 7, bit
/// (y & 7) * 8 + (x & 7)). A beam reaches a new cache line only when it enters another block,
/// where the linear box needs one at every step along y or z.
struct BlockedBits {
  std::uint64_t* bits;
  std::int64_t x0, y0, z0;  ///< the box's first voxel, multiples of 8
  std::int64_t nbx, nby, nbz;
  std::int64_t word(std::int64_t x, std::int64_t y, std::int64_t z) const {
    const std::int64_t rx = x - x0, ry = y - y0, rz = z - z0;
    return ((((rz >> 3) * nby + (ry >> 3)) * nbx + (rx >> 3)) << 3) | (rz & 7);
  }
  static int bit(std::int64_t x, std::int64_t y) {
    return static_cast<int>(((y & 7) << 3) | (x & 7));
  }
  void set(std::int64_t x, std::int64_t y, std::int64_t z) {
    bits[word(x, y, z)] |= std::uint64_t{1} << bit(x - x0, y - y0);
  }
};

// The portable walk: the SSE2 walk's operations one for one in plain double, so the same
// voxels on every CPU. Ordered `<` and `>` are false on NaN as cmplt_sd and comigt_sd are;
// min_sd(a, b) is `a < b ? a : b`; an axis not taken gets `+ 0.0` as `t + (mask & dt)` does.

/// The crossing parameters of one beam in the portable walk.
struct PortableT {
  double tx, ty, tz, dx, dy, dz, len;
};

inline void initT(const Beam& b, PortableT& t) {
  t.tx = b.t[0];
  t.ty = b.t[1];
  t.tz = b.t[2];
  t.dx = b.dt[0];
  t.dy = b.dt[1];
  t.dz = b.dt[2];
  t.len = b.length;
}

/// `v` where `mask` is all ones, +0.0 where it is zero (and_pd): no branch to mispredict.
inline double keepIf(std::int64_t mask, double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, 8);
  bits &= static_cast<std::uint64_t>(mask);
  std::memcpy(&v, &bits, 8);
  return v;
}

/// One crossing: OctoMap's choice, ties included (x if tx < ty and tx < tz, else y if
/// ty < tz, else z); the chosen axis's mask all ones, the others zero (as maskBits).
inline void crossPortable(PortableT& t, std::int64_t& bx, std::int64_t& by, std::int64_t& bz) {
  const bool x_lt_y = t.tx < t.ty;
  const bool mx = x_lt_y & (t.tx < t.tz);
  const bool my = !x_lt_y & (t.ty < t.tz);
  const bool mz = !(mx | my);
  bx = -static_cast<std::int64_t>(mx);
  by = -static_cast<std::int64_t>(my);
  bz = -static_cast<std::int64_t>(mz);
  t.tx = t.tx + keepIf(bx, t.dx);
  t.ty = t.ty + keepIf(by, t.dy);
  t.tz = t.tz + keepIf(bz, t.dz);
}

/// OctoMap's guard against accumulated rounding: the next crossing lies beyond the end.
inline bool pastEndPortable(const PortableT& t) {
  const double m = t.tx < t.ty ? t.tx : t.ty;
  return (m < t.tz ? m : t.tz) > t.len;
}

/// The portable walkBeam.
template <typename Sink>
inline void walkBeamPortable(const Beam& b, Sink& sink) {
  PortableT t;
  initT(b, t);
  std::int64_t kx = b.k[0], ky = b.k[1], kz = b.k[2];
  const std::int64_t sx = b.step[0], sy = b.step[1], sz = b.step[2];
  const std::int64_t ex = b.ke[0], ey = b.ke[1], ez = b.ke[2];
  for (;;) {
    std::int64_t bx, by, bz;
    crossPortable(t, bx, by, bz);
    kx += sx & bx;
    ky += sy & by;
    kz += sz & bz;
    if (((kx ^ ex) | (ky ^ ey) | (kz ^ ez)) == 0) return;
    if (pastEndPortable(t)) return;
    sink.markFree(kx, ky, kz);
  }
}

/// The portable LinearState.
struct PortableState {
  PortableT t;
  std::int64_t kx, ky, kz, sx, sy, sz, ix, iy, iz, ex, ey, ez, idx;
};

inline void initState(const Beam& b, const LinearBits& free, PortableState& s) {
  initT(b, s.t);
  s.kx = b.k[0];
  s.ky = b.k[1];
  s.kz = b.k[2];
  s.sx = b.step[0];
  s.sy = b.step[1];
  s.sz = b.step[2];
  s.ix = s.sx;
  s.iy = s.sy * free.row_bits;
  s.iz = s.sz * free.slice_bits;
  s.ex = b.ke[0];
  s.ey = b.ke[1];
  s.ez = b.ke[2];
  s.idx = free.index(s.kx, s.ky, s.kz);
}

/// The portable stepState.
inline bool stepState(PortableState& s, std::uint64_t* bits) {
  std::int64_t bx, by, bz;
  crossPortable(s.t, bx, by, bz);
  s.kx += s.sx & bx;
  s.ky += s.sy & by;
  s.kz += s.sz & bz;
  s.idx += (s.ix & bx) + (s.iy & by) + (s.iz & bz);
  if (((s.kx ^ s.ex) | (s.ky ^ s.ey) | (s.kz ^ s.ez)) == 0) return false;
  if (pastEndPortable(s.t)) return false;
  bits[s.idx >> 6] |= std::uint64_t{1} << (s.idx & 63);
  return true;
}

#if METRICMAP_RAY_SIMD

inline std::int64_t maskBits(__m128d m) { return _mm_cvtsi128_si64(_mm_castpd_si128(m)); }

/// Walks one beam to its end, the state in locals (registers).
template <typename Sink>
inline void walkBeam(const Beam& b, Sink& sink) {
  __m128d tx = _mm_set_sd(b.t[0]), ty = _mm_set_sd(b.t[1]), tz = _mm_set_sd(b.t[2]);
  const __m128d dx = _mm_set_sd(b.dt[0]), dy = _mm_set_sd(b.dt[1]), dz = _mm_set_sd(b.dt[2]);
  const __m128d len = _mm_set_sd(b.length);
  std::int64_t kx = b.k[0], ky = b.k[1], kz = b.k[2];
  const std::int64_t sx = b.step[0], sy = b.step[1], sz = b.step[2];
  const std::int64_t ex = b.ke[0], ey = b.ke[1], ez = b.ke[2];
  const __m128d ones = _mm_castsi128_pd(_mm_set1_epi64x(-1));
  for (;;) {
    // OctoMap's choice, ties included: x if tx < ty and tx < tz, else y if ty < tz, else z
    const __m128d x_lt_y = _mm_cmplt_sd(tx, ty);
    const __m128d mx = _mm_and_pd(x_lt_y, _mm_cmplt_sd(tx, tz));
    const __m128d my = _mm_andnot_pd(x_lt_y, _mm_cmplt_sd(ty, tz));
    const __m128d mz = _mm_andnot_pd(_mm_or_pd(mx, my), ones);
    tx = _mm_add_sd(tx, _mm_and_pd(mx, dx));
    ty = _mm_add_sd(ty, _mm_and_pd(my, dy));
    tz = _mm_add_sd(tz, _mm_and_pd(mz, dz));
    kx += sx & maskBits(mx);
    ky += sy & maskBits(my);
    kz += sz & maskBits(mz);
    if (((kx ^ ex) | (ky ^ ey) | (kz ^ ez)) == 0) return;
    // OctoMap's guard against accumulated rounding: the next crossing lies beyond the end
    if (_mm_comigt_sd(_mm_min_sd(_mm_min_sd(tx, ty), tz), len)) return;
    sink.markFree(kx, ky, kz);
  }
}

/// walkBeam's state marking into LinearBits, so that two beams can be stepped in one loop
/// (their steps are independent, which hides the latency of each).
struct LinearState {
  __m128d tx, ty, tz, dx, dy, dz, len;
  std::int64_t kx, ky, kz, sx, sy, sz, ix, iy, iz, ex, ey, ez, idx;
};

inline void initState(const Beam& b, const LinearBits& free, LinearState& s) {
  s.tx = _mm_set_sd(b.t[0]);
  s.ty = _mm_set_sd(b.t[1]);
  s.tz = _mm_set_sd(b.t[2]);
  s.dx = _mm_set_sd(b.dt[0]);
  s.dy = _mm_set_sd(b.dt[1]);
  s.dz = _mm_set_sd(b.dt[2]);
  s.len = _mm_set_sd(b.length);
  s.kx = b.k[0];
  s.ky = b.k[1];
  s.kz = b.k[2];
  s.sx = b.step[0];
  s.sy = b.step[1];
  s.sz = b.step[2];
  s.ix = s.sx;
  s.iy = s.sy * free.row_bits;
  s.iz = s.sz * free.slice_bits;
  s.ex = b.ke[0];
  s.ey = b.ke[1];
  s.ez = b.ke[2];
  s.idx = free.index(s.kx, s.ky, s.kz);
}

/// One step of OctoMap's loop; marks the voxel and returns true, or false when the beam is done.
inline bool stepState(LinearState& s, std::uint64_t* bits) {
  const __m128d x_lt_y = _mm_cmplt_sd(s.tx, s.ty);
  const __m128d mx = _mm_and_pd(x_lt_y, _mm_cmplt_sd(s.tx, s.tz));
  const __m128d my = _mm_andnot_pd(x_lt_y, _mm_cmplt_sd(s.ty, s.tz));
  const __m128d mz = _mm_andnot_pd(_mm_or_pd(mx, my), _mm_castsi128_pd(_mm_set1_epi64x(-1)));
  s.tx = _mm_add_sd(s.tx, _mm_and_pd(mx, s.dx));
  s.ty = _mm_add_sd(s.ty, _mm_and_pd(my, s.dy));
  s.tz = _mm_add_sd(s.tz, _mm_and_pd(mz, s.dz));
  const std::int64_t bx = maskBits(mx), by = maskBits(my), bz = maskBits(mz);
  s.kx += s.sx & bx;
  s.ky += s.sy & by;
  s.kz += s.sz & bz;
  s.idx += (s.ix & bx) + (s.iy & by) + (s.iz & bz);
  if (((s.kx ^ s.ex) | (s.ky ^ s.ey) | (s.kz ^ s.ez)) == 0) return false;
  if (_mm_comigt_sd(_mm_min_sd(_mm_min_sd(s.tx, s.ty), s.tz), s.len)) return false;
  bits[s.idx >> 6] |= std::uint64_t{1} << (s.idx & 63);
  return true;
}

/// The beams of a scan one at a time for the four-lane walk: marks each end's hit and the
/// origin's voxel as the pairwise walk does, skips beams that end in the origin's voxel.
template <typename Bits>
struct BeamFeed {
  const ScanUpdate::End* next;
  const ScanUpdate::End* last;
  const float* o;
  Key3 ko;
  double res;
  Bits* free;
  Bits* hits;
  bool pop(Beam& b) {
    while (next != last) {
      const ScanUpdate::End& end = *next++;
      if (end.hit) hits->set(end.k[0], end.k[1], end.k[2]);
      if (ko.v[0] == end.k[0] && ko.v[1] == end.k[1] && ko.v[2] == end.k[2]) continue;
      free->set(ko.v[0], ko.v[1], ko.v[2]);
      startBeam(o, end.e, ko, end.k, res, b);
      return true;
    }
    return false;
  }
};

/// Four beams' walks in the lanes of AVX2 registers (x86-64 with AVX2 only; chosen at run
/// time). Each lane does stepState's arithmetic, operation for operation, in double, so
/// the voxels are the same; a lane whose beam ends takes the next one. Voxels of lanes that are
/// done are marked in the spare word `spare` (bit index), which the caller clears.
__attribute__((target("avx2,bmi2"))) void walkFeedAvx2(BeamFeed<LinearBits>& feed, LinearBits& free,
                                                       std::int64_t spare) {
  alignas(32) double tx[4], ty[4], tz[4], dx[4], dy[4], dz[4], len[4];
  alignas(32) std::int64_t idx[4], eidx[4], ix[4], iy[4], iz[4], mark[4];
  int active = 0;
  Beam b;
  auto* bits = free.bits;
  const auto load = [&](int l) {  // no intrinsics in here: lambdas do not inherit the target
    if (!feed.pop(b)) {           // an idle lane: ends at once, marks the spare word
      tx[l] = ty[l] = tz[l] = dx[l] = dy[l] = dz[l] = 0.0;
      len[l] = -1.0;
      idx[l] = eidx[l] = spare;
      ix[l] = iy[l] = iz[l] = 0;
      active &= ~(1 << l);
      return;
    }
    tx[l] = b.t[0], ty[l] = b.t[1], tz[l] = b.t[2];
    dx[l] = b.dt[0], dy[l] = b.dt[1], dz[l] = b.dt[2];
    len[l] = b.length;
    idx[l] = free.index(b.k[0], b.k[1], b.k[2]);
    eidx[l] = free.index(b.ke[0], b.ke[1], b.ke[2]);
    ix[l] = b.step[0];
    iy[l] = b.step[1] * free.row_bits;
    iz[l] = b.step[2] * free.slice_bits;
    active |= 1 << l;
  };
  for (int l = 0; l < 4; ++l) load(l);
  if (active == 0) return;
  const __m256d ones = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  for (;;) {
    __m256d vtx = _mm256_load_pd(tx), vty = _mm256_load_pd(ty), vtz = _mm256_load_pd(tz);
    const __m256d vdx = _mm256_load_pd(dx), vdy = _mm256_load_pd(dy), vdz = _mm256_load_pd(dz);
    const __m256d vlen = _mm256_load_pd(len);
    __m256i vidx = _mm256_load_si256(reinterpret_cast<const __m256i*>(idx));
    const __m256i veidx = _mm256_load_si256(reinterpret_cast<const __m256i*>(eidx));
    const __m256i vix = _mm256_load_si256(reinterpret_cast<const __m256i*>(ix));
    const __m256i viy = _mm256_load_si256(reinterpret_cast<const __m256i*>(iy));
    const __m256i viz = _mm256_load_si256(reinterpret_cast<const __m256i*>(iz));
    const __m256i vspare = _mm256_set1_epi64x(spare);
    int done = 0;
    while (done == 0) {
      // OctoMap's choice, ties included: x if tx < ty and tx < tz, else y if ty < tz, else z
      const __m256d x_lt_y = _mm256_cmp_pd(vtx, vty, _CMP_LT_OS);
      const __m256d mx = _mm256_and_pd(x_lt_y, _mm256_cmp_pd(vtx, vtz, _CMP_LT_OS));
      const __m256d my = _mm256_andnot_pd(x_lt_y, _mm256_cmp_pd(vty, vtz, _CMP_LT_OS));
      const __m256d mz = _mm256_andnot_pd(_mm256_or_pd(mx, my), ones);
      vtx = _mm256_add_pd(vtx, _mm256_and_pd(mx, vdx));
      vty = _mm256_add_pd(vty, _mm256_and_pd(my, vdy));
      vtz = _mm256_add_pd(vtz, _mm256_and_pd(mz, vdz));
      vidx = _mm256_add_epi64(
          vidx, _mm256_add_epi64(_mm256_add_epi64(_mm256_and_si256(vix, _mm256_castpd_si256(mx)),
                                                  _mm256_and_si256(viy, _mm256_castpd_si256(my))),
                                 _mm256_and_si256(viz, _mm256_castpd_si256(mz))));
      // done: the end voxel reached, or the next crossing beyond the end (OctoMap's guard)
      const __m256i end = _mm256_cmpeq_epi64(vidx, veidx);
      const __m256d beyond =
          _mm256_cmp_pd(_mm256_min_pd(_mm256_min_pd(vtx, vty), vtz), vlen, _CMP_GT_OQ);
      const __m256i stop = _mm256_or_si256(end, _mm256_castpd_si256(beyond));
      _mm256_store_si256(reinterpret_cast<__m256i*>(mark), _mm256_blendv_epi8(vidx, vspare, stop));
      for (int l = 0; l < 4; ++l) bits[mark[l] >> 6] |= std::uint64_t{1} << (mark[l] & 63);
      done = _mm256_movemask_pd(_mm256_castsi256_pd(stop)) & active;
    }
    _mm256_store_pd(tx, vtx);
    _mm256_store_pd(ty, vty);
    _mm256_store_pd(tz, vtz);
    _mm256_store_si256(reinterpret_cast<__m256i*>(idx), vidx);
    for (int l = 0; l < 4; ++l) {
      if (done >> l & 1) load(l);
    }
    if (active == 0) return;
  }
}

// GCC 12's AVX-512 headers build constants from _mm512_undefined_*: -Wmaybe-uninitialized
// false positives.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
/// walkFeedAvx2's walk in the eight lanes of AVX-512 registers (chosen at run time where the
/// CPU has AVX-512F), marking into the blocked box: the same arithmetic per lane, the axis choice
/// in mask registers (a lane not stepping on an axis keeps its t where walkFeedAvx2 adds +0.0:
/// the same comparisons follow), each lane's voxel as its coordinates in the box, its word and
/// bit computed in the vector unit. Voxels of lanes that are done are marked in the spare word
/// `spare` (bit 0), which the caller clears.
__attribute__((target("avx512f,bmi2"))) void walkFeedAvx512(BeamFeed<BlockedBits>& feed,
                                                            BlockedBits& free, std::int64_t spare) {
  alignas(64) double tx[8], ty[8], tz[8], dx[8], dy[8], dz[8], len[8];
  alignas(64) std::int64_t rx[8], ry[8], rz[8], ex[8], ey[8], ez[8], sx[8], sy[8], sz[8];
  alignas(64) std::int64_t word[8], bit[8];
  unsigned active = 0;
  Beam b;
  auto* bits = free.bits;
  const auto load = [&](int l) {  // no intrinsics in here: lambdas do not inherit the target
    if (!feed.pop(b)) {           // an idle lane: ends at once, marks the spare word
      tx[l] = ty[l] = tz[l] = dx[l] = dy[l] = dz[l] = 0.0;
      len[l] = -1.0;
      rx[l] = ry[l] = rz[l] = ex[l] = ey[l] = ez[l] = sx[l] = sy[l] = sz[l] = 0;
      active &= ~(1u << l);
      return;
    }
    tx[l] = b.t[0], ty[l] = b.t[1], tz[l] = b.t[2];
    dx[l] = b.dt[0], dy[l] = b.dt[1], dz[l] = b.dt[2];
    len[l] = b.length;
    rx[l] = b.k[0] - free.x0, ry[l] = b.k[1] - free.y0, rz[l] = b.k[2] - free.z0;
    ex[l] = b.ke[0] - free.x0, ey[l] = b.ke[1] - free.y0, ez[l] = b.ke[2] - free.z0;
    sx[l] = b.step[0], sy[l] = b.step[1], sz[l] = b.step[2];
    active |= 1u << l;
  };
  for (int l = 0; l < 8; ++l) load(l);
  if (active == 0) return;
  const __m512i one = _mm512_set1_epi64(1), seven = _mm512_set1_epi64(7);
  const __m512i vnbx = _mm512_set1_epi64(free.nbx), vnby = _mm512_set1_epi64(free.nby);
  const __m512i vspare = _mm512_set1_epi64(spare), zero = _mm512_setzero_si512();
  for (;;) {
    __m512d vtx = _mm512_load_pd(tx), vty = _mm512_load_pd(ty), vtz = _mm512_load_pd(tz);
    const __m512d vdx = _mm512_load_pd(dx), vdy = _mm512_load_pd(dy), vdz = _mm512_load_pd(dz);
    const __m512d vlen = _mm512_load_pd(len);
    __m512i vrx = _mm512_load_si512(rx), vry = _mm512_load_si512(ry);
    __m512i vrz = _mm512_load_si512(rz);
    const __m512i vex = _mm512_load_si512(ex), vey = _mm512_load_si512(ey);
    const __m512i vez = _mm512_load_si512(ez);
    const __m512i vsx = _mm512_load_si512(sx), vsy = _mm512_load_si512(sy);
    const __m512i vsz = _mm512_load_si512(sz);
    unsigned done = 0;
    while (done == 0) {
      // OctoMap's choice, ties included: x if tx < ty and tx < tz, else y if ty < tz, else z
      const unsigned x_lt_y = _mm512_cmp_pd_mask(vtx, vty, _CMP_LT_OS);
      const auto mx = static_cast<__mmask8>(x_lt_y & _mm512_cmp_pd_mask(vtx, vtz, _CMP_LT_OS));
      const auto my = static_cast<__mmask8>(~x_lt_y & _mm512_cmp_pd_mask(vty, vtz, _CMP_LT_OS));
      const auto mz = static_cast<__mmask8>(~(mx | my));
      vtx = _mm512_mask_add_pd(vtx, mx, vtx, vdx);
      vty = _mm512_mask_add_pd(vty, my, vty, vdy);
      vtz = _mm512_mask_add_pd(vtz, mz, vtz, vdz);
      vrx = _mm512_mask_add_epi64(vrx, mx, vrx, vsx);
      vry = _mm512_mask_add_epi64(vry, my, vry, vsy);
      vrz = _mm512_mask_add_epi64(vrz, mz, vrz, vsz);
      // done: the end voxel reached, or the next crossing beyond the end (OctoMap's guard)
      const __mmask8 stop =
          (_mm512_cmpeq_epi64_mask(vrx, vex) & _mm512_cmpeq_epi64_mask(vry, vey) &
           _mm512_cmpeq_epi64_mask(vrz, vez)) |
          _mm512_cmp_pd_mask(_mm512_min_pd(_mm512_min_pd(vtx, vty), vtz), vlen, _CMP_GT_OQ);
      // the block (x fastest), its word z & 7, the bit (y & 7) * 8 + (x & 7); coordinates in
      // the box are >= 0 and the block counts < 2^32 (the box's size limit)
      const __m512i block = _mm512_add_epi64(
          _mm512_mul_epu32(_mm512_add_epi64(_mm512_mul_epu32(_mm512_srli_epi64(vrz, 3), vnby),
                                            _mm512_srli_epi64(vry, 3)),
                           vnbx),
          _mm512_srli_epi64(vrx, 3));
      const __m512i w = _mm512_or_si512(_mm512_slli_epi64(block, 3), _mm512_and_si512(vrz, seven));
      const __m512i pos = _mm512_or_si512(_mm512_slli_epi64(_mm512_and_si512(vry, seven), 3),
                                          _mm512_and_si512(vrx, seven));
      _mm512_store_si512(word, _mm512_mask_blend_epi64(stop, w, vspare));
      _mm512_store_si512(bit, _mm512_sllv_epi64(one, _mm512_mask_blend_epi64(stop, pos, zero)));
      for (int l = 0; l < 8; ++l) bits[word[l]] |= static_cast<std::uint64_t>(bit[l]);
      done = stop & active;
    }
    _mm512_store_pd(tx, vtx);
    _mm512_store_pd(ty, vty);
    _mm512_store_pd(tz, vtz);
    _mm512_store_si512(rx, vrx);
    _mm512_store_si512(ry, vry);
    _mm512_store_si512(rz, vrz);
    for (int l = 0; l < 8; ++l) {
      if (done >> l & 1) load(l);
    }
    if (active == 0) return;
  }
}

#pragma GCC diagnostic pop

bool haveAvx512() {
  static const bool yes =
      __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("bmi2") != 0;
  return yes;
}

bool haveAvx2() {
  static const bool yes =
      __builtin_cpu_supports("avx2") != 0 && __builtin_cpu_supports("bmi2") != 0;
  return yes;
}

#endif  // METRICMAP_RAY_SIMD

}  // namespace

const char* simdWalkName() {
#if METRICMAP_RAY_SIMD
  if (haveAvx512()) return "avx512 (8 lanes)";
  if (haveAvx2()) return "avx2 (4 lanes)";
  return "sse2 (2 lanes)";
#else
  return "portable";
#endif
}

namespace {

/// Two beams at a time until one ends, then the other alone (State: LinearState for the SSE2
/// walk, PortableState for the portable one).
template <typename State>
inline void walkPair(const Beam& a, const Beam& b, LinearBits& free) {
  State sa, sb;
  initState(a, free, sa);
  initState(b, free, sb);
  std::uint64_t* bits = free.bits;
  bool ra = true, rb = true;
  while (ra && rb) {
    ra = stepState(sa, bits);
    rb = stepState(sb, bits);
  }
  while (ra) ra = stepState(sa, bits);
  while (rb) rb = stepState(sb, bits);
}

/// Every beam of the scan into the box, two at a time: each end's hit, the origin's voxel for
/// each beam that leaves it, the voxels crossed.
template <typename State>
void walkPairs(const float o[3], const Key3& ko, const ScanUpdate& up, double res, LinearBits& free,
               LinearBits& hits) {
  Beam beams[2];
  int pending = 0;
  for (const ScanUpdate::End& end : up.ends) {
    if (end.hit) hits.set(hits.index(end.k[0], end.k[1], end.k[2]));
    if (ko.v[0] == end.k[0] && ko.v[1] == end.k[1] && ko.v[2] == end.k[2]) continue;
    free.set(free.index(ko.v[0], ko.v[1], ko.v[2]));
    startBeam(o, end.e, ko, end.k, res, beams[pending++]);
    if (pending == 2) {
      walkPair<State>(beams[0], beams[1], free);
      pending = 0;
    }
  }
  if (pending == 1) {
    State s;
    initState(beams[0], free, s);
    while (stepState(s, free.bits)) {
    }
  }
}

/// Moves the set bits of a LinearBits box into the scan's blocks (free or hit words), zeroing
/// them: each byte of a word is one block row of 8 voxels.
void harvest(LinearBits& box, std::int64_t words_per_row, std::int64_t rows_y, std::int64_t rows_z,
             bool hit, Marker& marker) {
  std::uint64_t* w = box.bits;
  for (std::int64_t z = 0; z < rows_z; ++z) {
    for (std::int64_t y = 0; y < rows_y; ++y) {
      for (std::int64_t xw = 0; xw < words_per_row; ++xw, ++w) {
        std::uint64_t word = *w;
        if (word == 0) continue;
        *w = 0;
        const std::int64_t gx = box.x0 + xw * 64, gy = box.y0 + y, gz = box.z0 + z;
        for (int byte = 0; byte < 8; ++byte, word >>= 8) {
          const std::uint64_t row = word & 0xff;
          if (row == 0) continue;
          const std::int64_t vx = gx + byte * 8;  // box.x0 is a multiple of 8
          ScanBlock& sb = marker.blockAt(vx >> kBlockShift, gy >> kBlockShift, gz >> kBlockShift);
          std::uint64_t* dst = hit ? sb.hit : sb.free;
          dst[gz & 7] |= row << ((gy & 7) * 8);
        }
      }
    }
  }
}

/// Moves the set bits of a BlockedBits box into the scan's blocks (free or hit words), zeroing
/// them: each 512-bit line is one block's words.
void harvestBlocked(BlockedBits& box, bool hit, Marker& marker) {
  std::uint64_t* line = box.bits;
  for (std::int64_t bz = 0; bz < box.nbz; ++bz) {
    for (std::int64_t by = 0; by < box.nby; ++by) {
      for (std::int64_t bx = 0; bx < box.nbx; ++bx, line += kBlockWords) {
        std::uint64_t any = 0;
        for (int w = 0; w < kBlockWords; ++w) any |= line[w];
        if (any == 0) continue;
        ScanBlock& sb = marker.blockAt((box.x0 >> kBlockShift) + bx, (box.y0 >> kBlockShift) + by,
                                       (box.z0 >> kBlockShift) + bz);
        std::uint64_t* dst = hit ? sb.hit : sb.free;
        for (int w = 0; w < kBlockWords; ++w) {
          dst[w] |= line[w];
          line[w] = 0;
        }
      }
    }
  }
}

/// Walks every beam of the scan, marking the voxels from the origin's up to, not including,
/// the end's as free and the end voxels of unclipped beams as hits.
template <typename Sink>
void walkAll(const float o[3], const Key3& ko, const ScanUpdate& up, double res, bool portable,
             Sink& sink) {
  Beam b;
  for (const ScanUpdate::End& end : up.ends) {
    if (end.hit) sink.markHit(end.k[0], end.k[1], end.k[2]);
    if (ko.v[0] == end.k[0] && ko.v[1] == end.k[1] && ko.v[2] == end.k[2]) continue;
    sink.markFree(ko.v[0], ko.v[1], ko.v[2]);
    startBeam(o, end.e, ko, end.k, res, b);
#if METRICMAP_RAY_SIMD
    if (!portable) {
      walkBeam(b, sink);
      continue;
    }
#endif
    walkBeamPortable(b, sink);
  }
}

constexpr std::int64_t kDenseWordLimit = std::int64_t{1} << 23;  // 2 x 64 MiB of bits
/// Below this on every axis (m) an end's float offset from the origin squares to less than the
/// smallest normal float: the walk could not find its direction.
constexpr float kAtOrigin = 1e-18f;

}  // namespace

void uniteScanUpdates(ScanUpdate& into, const ScanUpdate& from, std::size_t max_blocks,
                      double resolution) {
  Marker marker(into, max_blocks, resolution);
  for (const ScanBlock& b : from.blocks) {
    const VoxelKey k = unpackVoxelKey(b.key);
    ScanBlock& t = marker.blockAt(k.x, k.y, k.z);
    for (int w = 0; w < kBlockWords; ++w) {
      t.free[w] |= b.free[w];
      t.hit[w] |= b.hit[w];
    }
  }
}

namespace {

/// The scan's beams as end points and end keys (max_range cut applied, non-finite points
/// counted and dropped), and the key box they span (`lo`, `hi`, the origin's key included).
RayCastCounts collectEnds(const RayCastInput& in, const Key3& ko, ScanUpdate& out,
                          std::int64_t lo[3], std::int64_t hi[3]) {
  RayCastCounts counts;
  const double res = in.resolution;
  const double inv_res = 1.0 / res;
  const float* o = in.origin;
  const bool cut_enabled = std::isfinite(in.max_range);
  const auto max_range_f = static_cast<float>(in.max_range);
  for (int i = 0; i < 3; ++i) lo[i] = hi[i] = ko.v[i];
  out.ends.reserve(in.count);
  const auto* bytes = reinterpret_cast<const unsigned char*>(in.xyz);
  for (std::size_t n = 0; n < in.count; ++n) {
    const auto* src = reinterpret_cast<const float*>(bytes + n * in.stride_bytes);
    float p[3] = {src[0], src[1], src[2]};
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      ++counts.non_finite;
      continue;
    }
    if (in.pose != nullptr) {
      const float* m = in.pose;
      const float x = p[0], y = p[1], z = p[2];
      p[0] = m[0] * x + m[1] * y + m[2] * z + m[3];
      p[1] = m[4] * x + m[5] * y + m[6] * z + m[7];
      p[2] = m[8] * x + m[9] * y + m[10] * z + m[11];
    }
    ++counts.beams;
    // OctoMap's test: the float difference, its squared norm in float, sqrt in double.
    const float d[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
    const double norm = std::sqrt(static_cast<double>(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    ScanUpdate::End end;
    if (!cut_enabled || norm <= in.max_range) {
      end.hit = 1;
      // An end within 1e-18 m of the origin is the origin: the walk's float direction would
      // underflow (squared length 0) and never reach the neighbouring voxel it may lie in.
      const bool at_origin =
          std::fabs(d[0]) < kAtOrigin && std::fabs(d[1]) < kAtOrigin && std::fabs(d[2]) < kAtOrigin;
      for (int i = 0; i < 3; ++i) end.e[i] = at_origin ? o[i] : p[i];
    } else {
      ++counts.cut;
      end.hit = 0;
      const auto f = static_cast<float>(norm);
      for (int i = 0; i < 3; ++i) end.e[i] = o[i] + (d[i] / f) * max_range_f;
    }
    Key3 ke;
    if (!keyOf(end.e, inv_res, ke)) outsideKeySpace(end.e, res);
    for (int i = 0; i < 3; ++i) {
      end.k[i] = static_cast<std::int32_t>(ke.v[i]);
      lo[i] = std::min(lo[i], ke.v[i]);
      hi[i] = std::max(hi[i], ke.v[i]);
    }
    out.ends.push_back(end);
  }
  return counts;
}

#if METRICMAP_RAY_SIMD
/// The eight-lane walk over a box of whole blocks (multiples of 8 on every axis); false when
/// the box is too large for the dense bitmap (nothing done then).
bool walkBlockedAvx512(const RayCastInput& in, const Key3& ko, const std::int64_t lo[3],
                       const std::int64_t hi[3], ScanUpdate& out, Marker& marker) {
  const std::int64_t bx0 = lo[0] >> kBlockShift, by0 = lo[1] >> kBlockShift;
  const std::int64_t bz0 = lo[2] >> kBlockShift;
  BlockedBits free{nullptr,
                   bx0 * kBlockEdge,
                   by0 * kBlockEdge,
                   bz0 * kBlockEdge,
                   (hi[0] >> kBlockShift) - bx0 + 1,
                   (hi[1] >> kBlockShift) - by0 + 1,
                   (hi[2] >> kBlockShift) - bz0 + 1};
  const std::int64_t box_words = free.nbx * free.nby * free.nbz * kBlockWords;
  if (box_words > kDenseWordLimit) return false;
  const auto words = static_cast<std::size_t>(box_words);
  // free bits, hit bits, and one spare word for the idle lanes
  if (out.dense.size() < 2 * words + 1) out.dense.assign(2 * words + 1, 0);
  free.bits = out.dense.data();
  BlockedBits hits = free;
  hits.bits = out.dense.data() + words;
  BeamFeed<BlockedBits> feed{out.ends.data(),
                             out.ends.data() + out.ends.size(),
                             in.origin,
                             ko,
                             in.resolution,
                             &free,
                             &hits};
  walkFeedAvx512(feed, free, static_cast<std::int64_t>(2 * words));
  out.dense[2 * words] = 0;
  try {
    harvestBlocked(free, false, marker);
    harvestBlocked(hits, true, marker);
  } catch (...) {  // too many blocks: leave the reused bitmap clear for the next scan
    std::fill(out.dense.begin(), out.dense.begin() + static_cast<std::ptrdiff_t>(2 * words), 0);
    throw;
  }
  return true;
}
#endif

/// The walk over a box of 64-bit rows (x from a multiple of 64); false when the box is too
/// large for the dense bitmap (nothing done then).
bool walkLinear(const RayCastInput& in, const Key3& ko, const std::int64_t lo[3],
                const std::int64_t hi[3], bool portable, ScanUpdate& out, Marker& marker) {
  const float* o = in.origin;
  const double res = in.resolution;
  const std::int64_t x0 = (lo[0] >> 6) * 64;  // a multiple of 64 (and of 8)
  const std::int64_t words_per_row = ((hi[0] - x0) >> 6) + 1;
  const std::int64_t ny = hi[1] - lo[1] + 1, nz = hi[2] - lo[2] + 1;
  if (words_per_row * ny * nz > kDenseWordLimit) return false;
  const auto words = static_cast<std::size_t>(words_per_row * ny * nz);
  // free bits, hit bits, and one spare word for the four-lane walk's idle lanes
  if (out.dense.size() < 2 * words + 1) out.dense.assign(2 * words + 1, 0);
  LinearBits free{out.dense.data(), x0, lo[1], lo[2], words_per_row * 64, words_per_row * 64 * ny};
  LinearBits hits = free;
  hits.bits = out.dense.data() + words;
  if (portable) {
    walkPairs<PortableState>(o, ko, out, res, free, hits);
  } else {
#if METRICMAP_RAY_SIMD
    BeamFeed<LinearBits> feed{
        out.ends.data(), out.ends.data() + out.ends.size(), o, ko, res, &free, &hits};
    if (in.lanes >= 4 && haveAvx2()) {
      walkFeedAvx2(feed, free, static_cast<std::int64_t>(2 * words) * 64);
      out.dense[2 * words] = 0;
    } else {
      walkPairs<LinearState>(o, ko, out, res, free, hits);
    }
#endif
  }
  try {
    harvest(free, words_per_row, ny, nz, false, marker);
    harvest(hits, words_per_row, ny, nz, true, marker);
  } catch (...) {  // too many blocks: leave the reused bitmap clear for the next scan
    std::fill(out.dense.begin(), out.dense.begin() + static_cast<std::ptrdiff_t>(2 * words), 0);
    throw;
  }
  return true;
}

}  // namespace

RayCastCounts castRays(const RayCastInput& in, ScanUpdate& out) {
  out.clear();
  out.ends.clear();
  const bool portable = rayPath() == RayPath::Portable;  // once per scan
  Key3 ko;
  if (!keyOf(in.origin, 1.0 / in.resolution, ko)) outsideKeySpace(in.origin, in.resolution);
  std::int64_t lo[3], hi[3];
  const RayCastCounts counts = collectEnds(in, ko, out, lo, hi);
  // The box of the scan. OctoMap's walk may step one voxel past an end voxel when a beam ends
  // within rounding of a voxel edge (it then stops on the length test), so the box has a
  // margin of 2 voxels on every side.
  for (int i = 0; i < 3; ++i) {
    lo[i] -= 2;
    hi[i] += 2;
  }
  Marker marker(out, in.max_blocks, in.resolution);
#if METRICMAP_RAY_SIMD
  if (!portable && in.lanes >= 8 && haveAvx512() && walkBlockedAvx512(in, ko, lo, hi, out, marker))
    return counts;
#endif
  if (!walkLinear(in, ko, lo, hi, portable, out, marker))
    walkAll(in.origin, ko, out, in.resolution, portable, marker);
  return counts;
}

}  // namespace metricmap::detail
