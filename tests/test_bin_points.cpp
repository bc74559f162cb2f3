// mapping/bin_points: Active Neural SLAM's bin_points against a plain reference written here from
// its published numpy definition (np.round half to even, np.digitize, the validity mask).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include "metricmap/mapping/bin_points.h"

namespace {

/// np.round: half to even, by hand (no nearbyint: floor and compare).
double roundHalfEven(double v) {
  const double f = std::floor(v);
  const double d = v - f;
  if (d < 0.5) return f;
  if (d > 0.5) return f + 1.0;
  return std::fmod(f, 2.0) == 0.0 ? f : f + 1.0;
}

/// np.digitize(z, bins) for increasing bins: the number of edges <= z (NaN: all).
std::size_t digitizeIncreasing(double z, const std::vector<double>& bins) {
  if (std::isnan(z)) return bins.size();
  std::size_t k = 0;
  for (double b : bins) k += b <= z ? 1 : 0;
  return k;
}

struct Reference {
  std::vector<double> counts;
  std::vector<bool> valid;
};

/// The definition for double input, one frame, increasing bins, values well inside int32.
Reference reference(const std::vector<double>& xyz, std::int64_t m, const std::vector<double>& bins,
                    double r) {
  const std::size_t n = xyz.size() / 3, nz = bins.size() + 1;
  Reference out{std::vector<double>(static_cast<std::size_t>(m * m) * nz, 0.0),
                std::vector<bool>(n, false)};
  for (std::size_t i = 0; i < n; ++i) {
    const double x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
    if (std::isnan(x) || std::isnan(y)) continue;  // NaN y casts to INT32_MIN: invalid
    const double xb = roundHalfEven(x / r), yb = roundHalfEven(y / r);
    if (xb < 0 || yb < 0 || xb >= static_cast<double>(m) || yb >= static_cast<double>(m)) continue;
    out.valid[i] = true;
    const std::size_t cell =
        static_cast<std::size_t>(yb) * static_cast<std::size_t>(m) + static_cast<std::size_t>(xb);
    out.counts[cell * nz + digitizeIncreasing(z, bins)] += 1.0;
  }
  return out;
}

TEST(BinPoints, EqualsThePlainDefinitionOnRandomPointsWithTies) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 22.0), h(-0.5, 2.5);
  std::vector<double> xyz;
  for (int i = 0; i < 5000; ++i) {
    xyz.push_back(u(rng));
    xyz.push_back(u(rng));
    xyz.push_back(h(rng));
  }
  // Ties (x / r exactly k + 0.5), a NaN x, a NaN z, a point on a bin edge.
  const std::vector<double> extra = {2.5, 3.5, 0.1, 0.5,          1.5, 1.0, std::nan(""), 1.0,
                                     1.0, 4.0, 4.0, std::nan(""), 5.0, 5.0, 1.0};
  xyz.insert(xyz.end(), extra.begin(), extra.end());
  const std::vector<double> bins = {0.1, 1.0};
  metricmap::BinPointsParams p;
  p.map_size = 20;
  p.z_bins = bins;
  p.xy_resolution = 1.0;
  const std::size_t n = xyz.size() / 3;
  std::vector<double> counts(static_cast<std::size_t>(p.map_size * p.map_size) * 3, 0.0);
  std::unique_ptr<bool[]> valid(new bool[n]);
  metricmap::binPoints<double>(xyz.data(), 1, n, 3, p, counts.data(), valid.get());
  const Reference ref = reference(xyz, p.map_size, bins, p.xy_resolution);
  ASSERT_EQ(counts.size(), ref.counts.size());
  for (std::size_t k = 0; k < counts.size(); ++k) EXPECT_EQ(counts[k], ref.counts[k]) << k;
  std::size_t n_valid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(valid[i], ref.valid[i]) << i;
    n_valid += valid[i] ? 1 : 0;
  }
  EXPECT_GT(n_valid, n / 2);
  EXPECT_LT(n_valid, n);
  // The ties round to even: (2.5, 3.5, z 0.1 on an edge) -> x bin 2, y bin 4, z bin 1;
  // (0.5, 1.5, z 1.0) -> 0, 2, z bin 2.
  EXPECT_GE(counts[(4 * 20 + 2) * 3 + 1], 1.0);
  EXPECT_GE(counts[(2 * 20 + 0) * 3 + 2], 1.0);
}

TEST(BinPoints, FloatInputAndFramesWithAFourthChannel) {
  // Two frames of three points, channels = 4: the fourth value is ignored.
  const std::vector<float> xyzw = {1.2f,  0.4f, 0.5f, 9.f, 2.6f, 1.5f, 3.0f, 9.f,
                                   -0.6f, 1.f,  1.f,  9.f, 0.0f, 0.0f, -1.f, 9.f,
                                   2.5f,  2.5f, 0.2f, 9.f, 3.0f, 0.f,  0.f,  9.f};
  metricmap::BinPointsParams p;
  p.map_size = 3;
  p.z_bins = {0.1, 1.0};
  p.xy_resolution = 1.0;
  std::vector<double> counts(2 * 3 * 3 * 3, 0.0);
  bool valid[6];
  metricmap::binPoints<float>(xyzw.data(), 2, 3, 4, p, counts.data(), valid);
  for (std::size_t f = 0; f < 2; ++f) {
    std::vector<double> frame;
    for (std::size_t i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) frame.push_back(xyzw[(f * 3 + i) * 4 + c]);
    const Reference ref = reference(frame, 3, p.z_bins, 1.0);
    for (std::size_t k = 0; k < ref.counts.size(); ++k)
      EXPECT_EQ(counts[f * 27 + k], ref.counts[k]) << f << " " << k;
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(valid[f * 3 + i], ref.valid[i]) << f << " " << i;
  }
}

TEST(BinPoints, RefusesBadParameters) {
  metricmap::BinPointsParams p;
  p.z_bins = {0.1, 1.0};
  p.map_size = 0;
  EXPECT_THROW(metricmap::validateBinPointsParams(p), std::invalid_argument);
  p.map_size = 10;
  p.xy_resolution = 0.0;
  EXPECT_THROW(metricmap::validateBinPointsParams(p), std::invalid_argument);
  p.xy_resolution = std::numeric_limits<double>::infinity();
  EXPECT_THROW(metricmap::validateBinPointsParams(p), std::invalid_argument);
  p.xy_resolution = 0.05;
  p.z_bins = {0.1, std::nan(""), 1.0};
  EXPECT_THROW(metricmap::validateBinPointsParams(p), std::invalid_argument);
  p.z_bins = {0.1, 1.0, 0.5};
  EXPECT_THROW(metricmap::validateBinPointsParams(p), std::invalid_argument);
  p.z_bins = {1.0, 0.1};
  EXPECT_NO_THROW(metricmap::validateBinPointsParams(p));
  p.map_size = 40000;
  EXPECT_THROW(metricmap::validateBinPointsParams(p), std::invalid_argument);
}

}  // namespace
