#pragma once
/// \file bin_points.h
/// \brief Active Neural SLAM's `bin_points` (env/utils/depth_utils.py) in C++: counts of points
/// per (row = y bin, column = x bin, height bin), bit for bit what its numpy code computes.
///
/// Per point: X_bin = int32(round_half_even(x / r)), Y_bin likewise (the division and the
/// rounding in the input's precision, r cast to it; a value outside int32 becomes INT32_MIN, as
/// numpy's cast on x86), Z_bin = np.digitize(z, z_bins) (NaN z: len(z_bins) for increasing
/// edges, 0 for decreasing ones); valid iff 0 <= X_bin, Y_bin < map_size and x is not NaN.
/// HeightMap (height_map.h) is the library's own top-down map: its cells are centred on the
/// camera and floored; this is the course's drop-in function, used by metricmap.bin_points.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace metricmap {

struct BinPointsParams {
  std::int64_t map_size = 0;   ///< > 0
  std::vector<double> z_bins;  ///< monotonic (non-decreasing or non-increasing), no NaN
  double xy_resolution = 1.0;  ///< finite, non-zero
};

/// \throws std::invalid_argument naming the bad value
void validateBinPointsParams(const BinPointsParams& params);

/// \brief Bin `frames` frames of `pixels` points each; point i of frame f has x, y, z at
/// xyz[(f * pixels + i) * channels + 0..2] (channels >= 3).
/// \param[out] counts frames x map_size x map_size x (len(z_bins) + 1), zeroed by the caller
/// \param[out] valid frames x pixels
template <typename T>
void binPoints(const T* xyz, std::size_t frames, std::size_t pixels, std::size_t channels,
               const BinPointsParams& params, double* counts, bool* valid);

}  // namespace metricmap
