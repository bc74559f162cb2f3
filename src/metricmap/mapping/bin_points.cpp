#include "metricmap/mapping/bin_points.h"

#include <cmath>
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

/// np.round (half to even) of v / r, computed in T as numpy does for a T array.
template <typename T>
inline std::int64_t xyBin(T v, T r) {
  return toInt32(static_cast<double>(std::nearbyint(v / r)));
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
  for (std::size_t f = 0; f < frames; ++f) {
    double* c = counts + f * per_frame;
    for (std::size_t i = 0; i < pixels; ++i) {
      const T* p = xyz + (f * pixels + i) * channels;
      const std::int64_t xb = in_t ? xyBin<T>(p[0], r) : xyBin<double>(p[0], params.xy_resolution);
      const std::int64_t yb = in_t ? xyBin<T>(p[1], r) : xyBin<double>(p[1], params.xy_resolution);
      const bool ok = !std::isnan(p[0]) && xb >= 0 && xb < m && yb >= 0 && yb < m;
      valid[f * pixels + i] = ok;
      if (!ok) continue;
      const double z = static_cast<double>(p[2]);
      std::size_t zb = 0;
      if (increasing) {  // searchsorted(bins, z, 'right'): edges <= z; NaN sorts last
        if (std::isnan(z)) {
          zb = nb;
        } else {
          while (zb < nb && bins[zb] <= z) ++zb;
        }
      } else {  // len - searchsorted(bins[::-1], z, 'right'): len - (edges <= z)
        std::size_t below = 0;
        if (std::isnan(z)) {
          below = nb;
        } else {
          for (double b : bins) below += b <= z ? 1 : 0;
        }
        zb = nb - below;
      }
      c[(static_cast<std::size_t>(yb) * static_cast<std::size_t>(m) +
         static_cast<std::size_t>(xb)) *
            nz +
        zb] += 1.0;
    }
  }
}

template void binPoints<float>(const float*, std::size_t, std::size_t, std::size_t,
                               const BinPointsParams&, double*, bool*);
template void binPoints<double>(const double*, std::size_t, std::size_t, std::size_t,
                                const BinPointsParams&, double*, bool*);

}  // namespace metricmap
