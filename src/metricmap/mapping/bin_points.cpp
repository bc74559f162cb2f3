#include "metricmap/mapping/bin_points.h"

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <limits>
#include <sstream>
#include <stdexcept>

namespace metricmap {

namespace {

/// numpy's float -> int32 cast on x86 (cvttss2si / cvttsd2si): truncation, INT32_MIN when the
/// value is NaN or out of range. The values here are already integral (rounded).
inline std::int64_t toInt32(double v) {
  if (!(v >= -2147483648.0 && v < 2147483648.0)) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int64_t>(static_cast<std::int32_t>(v));
}

/// Round half to even in the default rounding mode, as std::nearbyint does, without a libm
/// call: adding and subtracting 1.5 * 2^(mantissa bits) leaves the nearest integer (ties to
/// even) for |v| < 2^(mantissa bits - 1); larger values are integers already; NaN stays NaN.
inline double roundEven(double v) {
  constexpr double kShift = 6755399441055744.0;                          // 1.5 * 2^52
  return std::fabs(v) < 2251799813685248.0 ? (v + kShift) - kShift : v;  // 2^51
}
inline float roundEven(float v) {
  constexpr float kShift = 12582912.0f;                          // 1.5 * 2^23
  return std::fabs(v) < 4194304.0f ? (v + kShift) - kShift : v;  // 2^22
}

/// roundEven(x / r) and roundEven(y / r) of a point, both quotients from one division where
/// the CPU divides two doubles at once (SSE2: x86-64's baseline).
template <typename T>
inline void binsOf(const T* p, T r, T& xb, T& yb) {
  xb = roundEven(p[0] / r);
  yb = roundEven(p[1] / r);
}
#if defined(__SSE2__)
template <>
inline void binsOf<double>(const double* p, double r, double& xb, double& yb) {
  const __m128d q = _mm_div_pd(_mm_loadu_pd(p), _mm_set1_pd(r));
  alignas(16) double out[2];
  _mm_store_pd(out, q);
  xb = roundEven(out[0]);
  yb = roundEven(out[1]);
}
#endif

/// np.round (half to even) of v / r, computed in T as numpy does for a T array.
template <typename T>
inline std::int64_t xyBin(T v, T r) {
  return toInt32(static_cast<double>(roundEven(v / r)));
}

/// +1 non-decreasing, -1 non-increasing (numpy's _monotonicity; constant counts as increasing).
int monotonicity(const std::vector<double>& b) {
  bool up = true, down = true;
  for (std::size_t i = 1; i < b.size(); ++i) {
    if (b[i] < b[i - 1]) up = false;
    if (b[i] > b[i - 1]) down = false;
  }
  return up ? 1 : (down ? -1 : 0);
}

}  // namespace

void validateBinPointsParams(const BinPointsParams& p) {
  std::ostringstream msg;
  if (p.map_size <= 0) {
    msg << "map_size must be > 0, got " << p.map_size;
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(p.xy_resolution) || p.xy_resolution == 0.0) {
    msg << "xy_resolution must be finite and non-zero, got " << p.xy_resolution;
    throw std::invalid_argument(msg.str());
  }
  for (double b : p.z_bins) {
    if (std::isnan(b)) throw std::invalid_argument("z_bins must not contain NaN");
  }
  if (monotonicity(p.z_bins) == 0)
    throw std::invalid_argument("z_bins must be monotonically increasing or decreasing");
  const double cells = static_cast<double>(p.map_size) * static_cast<double>(p.map_size) *
                       static_cast<double>(p.z_bins.size() + 1);
  if (cells > 2147483647.0) {
    msg << "map_size " << p.map_size << " with " << p.z_bins.size() + 1 << " height bins makes "
        << cells << " bins, more than numpy's int32 index allows";
    throw std::invalid_argument(msg.str());
  }
}

template <typename T>
void binPoints(const T* xyz, std::size_t frames, std::size_t pixels, std::size_t channels,
               const BinPointsParams& params, double* counts, bool* valid) {
  const std::int64_t m = params.map_size;
  const std::vector<double>& bins = params.z_bins;
  const std::size_t nb = bins.size();
  const std::size_t nz = nb + 1;
  const bool increasing = monotonicity(bins) >= 0;
  // numpy divides a T array by a Python float in T, unless the float does not fit T.
  const bool in_t =
      std::abs(params.xy_resolution) <= static_cast<double>(std::numeric_limits<T>::max());
  const T r = static_cast<T>(params.xy_resolution);
  const std::size_t per_frame = static_cast<std::size_t>(m) * static_cast<std::size_t>(m) * nz;
  // np.digitize's bin of z: searchsorted(bins, z, 'right') for increasing edges (edges <= z),
  // len - searchsorted(bins[::-1], z, 'right') for decreasing ones; NaN sorts last.
  // (the edges copied beside the loop: a few registers, not a vector's heap array)
  constexpr std::size_t kInline = 8;
  double edges[kInline] = {};
  const bool inline_edges = nb <= kInline;
  if (inline_edges) std::copy(bins.begin(), bins.end(), edges);
  const auto zBin = [&](double z) -> std::size_t {
    if (std::isnan(z)) return increasing ? nb : 0;
    std::size_t below = 0;
    if (inline_edges) {
      for (std::size_t e = 0; e < nb; ++e) below += edges[e] <= z ? 1 : 0;
    } else {
      for (double b : bins) below += b <= z ? 1 : 0;
    }
    return increasing ? below : nb - below;
  };
  const auto mf = static_cast<T>(m);
  for (std::size_t f = 0; f < frames; ++f) {
    double* c = counts + f * per_frame;
    const T* frame = xyz + f * pixels * channels;
    bool* ok_out = valid + f * pixels;
    if (in_t) {
      // Branch-free bins: the rounding trick is exact wherever the bin can be valid (0 <= bin <
      // map_size < 2^22); NaN, infinities and huge values fail the range test as numpy's
      // INT32_MIN does.
      for (std::size_t i = 0; i < pixels; ++i) {
        const T* p = frame + i * channels;
        T xb, yb;
        binsOf(p, r, xb, yb);
        const bool ok = xb >= T(0) && xb < mf && yb >= T(0) && yb < mf;
        ok_out[i] = ok;
        if (!ok) continue;
        const std::size_t cell = static_cast<std::size_t>(yb) * static_cast<std::size_t>(m) +
                                 static_cast<std::size_t>(xb);
        c[cell * nz + zBin(static_cast<double>(p[2]))] += 1.0;
      }
      continue;
    }
    for (std::size_t i = 0; i < pixels; ++i) {
      const T* p = frame + i * channels;
      const std::int64_t xb = xyBin<double>(p[0], params.xy_resolution);
      const std::int64_t yb = xyBin<double>(p[1], params.xy_resolution);
      const bool ok = !std::isnan(p[0]) && xb >= 0 && xb < m && yb >= 0 && yb < m;
      ok_out[i] = ok;
      if (!ok) continue;
      c[(static_cast<std::size_t>(yb) * static_cast<std::size_t>(m) +
         static_cast<std::size_t>(xb)) *
            nz +
        zBin(static_cast<double>(p[2]))] += 1.0;
    }
  }
}

template void binPoints<float>(const float*, std::size_t, std::size_t, std::size_t,
                               const BinPointsParams&, double*, bool*);
template void binPoints<double>(const double*, std::size_t, std::size_t, std::size_t,
                                const BinPointsParams&, double*, bool*);

}  // namespace metricmap
