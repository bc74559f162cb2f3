// Grids that start at a given point or half a cell below the cloud's minimum (Open3D's
// voxel_down_sample), and the per-point cell rows, against a plain binning written here.
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/grid/grid_kernel.h"

namespace metricmap {
namespace {

using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>;

struct RefCell {
  std::uint64_t count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
};

std::vector<float> randomCloud(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-7.3f, 11.9f);
  std::vector<float> xyz(3 * n);
  for (float& v : xyz) v = u(rng);
  return xyz;
}

PointSpan spanOf(const std::vector<float>& xyz) {
  PointSpan s;
  s.base = xyz.data();
  s.stride = 3 * sizeof(float);
  s.size = xyz.size() / 3;
  return s;
}

/// Bins every finite point by floor((p - start) / cell) in double; checks cells (linear order:
/// z, then y, then x), counts, means and each point's row.
void expectBinnedFrom(const std::vector<float>& xyz, const Eigen::Vector3d& start, double cell,
                      const GridResult& r) {
  std::map<Key, RefCell> ref;
  std::vector<Key> key_of(xyz.size() / 3);
  std::vector<bool> finite(xyz.size() / 3);
  for (std::size_t i = 0; i < key_of.size(); ++i) {
    const Eigen::Vector3d p(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    finite[i] = p.allFinite();
    if (!finite[i]) continue;
    const Eigen::Vector3d t = (p - start) / cell;
    key_of[i] = Key{static_cast<std::int64_t>(std::floor(t.z())),
                    static_cast<std::int64_t>(std::floor(t.y())),
                    static_cast<std::int64_t>(std::floor(t.x()))};
    RefCell& c = ref[key_of[i]];
    ++c.count;
    c.sum += p;
  }
  ASSERT_EQ(r.cells.size(), ref.size());
  std::map<Key, std::int64_t> row_of;
  std::size_t row = 0;
  for (const auto& [key, c] : ref) {
    const GridCell& g = r.cells[row];
    EXPECT_EQ(g.index[2], std::get<0>(key));
    EXPECT_EQ(g.index[1], std::get<1>(key));
    EXPECT_EQ(g.index[0], std::get<2>(key));
    EXPECT_EQ(g.count, c.count);
    EXPECT_LT((g.mean - c.sum / static_cast<double>(c.count)).norm(), 1e-9);
    row_of[key] = static_cast<std::int64_t>(row++);
  }
  ASSERT_EQ(r.point_cells.size(), key_of.size());
  for (std::size_t i = 0; i < key_of.size(); ++i) {
    EXPECT_EQ(r.point_cells[i], finite[i] ? row_of[key_of[i]] : -1) << "point " << i;
  }
  EXPECT_EQ(r.layout.origin, start);
  EXPECT_EQ(r.layout.cell_size, cell);
}

TEST(GridOrigin, StartsAtAGivenPoint) {
  std::vector<float> xyz = randomCloud(20000, 7);
  xyz[30] = std::numeric_limits<float>::quiet_NaN();
  GridParams params;
  params.cell_size = 0.3f;
  params.exact_cell_size = 0.3;
  params.origin = GridOrigin::Point;
  params.origin_point = Eigen::Vector3d(0.123, -4.5, 2.0);
  params.point_cells = true;
  params.threads = 2;
  const GridResult r = buildGrid(spanOf(xyz), params);
  expectBinnedFrom(xyz, params.origin_point, 0.3, r);
  EXPECT_EQ(r.stats.skipped_points, 1u);
}

TEST(GridOrigin, HalfACellBelowTheMinimumAsOpen3D) {
  const std::vector<float> xyz = randomCloud(20000, 11);
  Eigen::Vector3d mn = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < xyz.size(); i += 3)
    mn = mn.cwiseMin(Eigen::Vector3d(xyz[i], xyz[i + 1], xyz[i + 2]));
  GridParams params;
  params.cell_size = 0.1f;
  params.exact_cell_size = 0.1;
  params.origin = GridOrigin::HalfCellBelowMinimum;
  params.point_cells = true;
  const GridResult r = buildGrid(spanOf(xyz), params);
  expectBinnedFrom(xyz, mn - Eigen::Vector3d(0.1, 0.1, 0.1) * 0.5, 0.1, r);
}

TEST(GridOrigin, PointCellsOfTheOtherOrigins) {
  const std::vector<float> xyz = randomCloud(5000, 3);
  for (GridOrigin origin : {GridOrigin::CloudMinimum, GridOrigin::WorldAligned}) {
    GridParams params;
    params.cell_size = 0.5f;
    params.origin = origin;
    params.point_cells = true;
    const GridResult r = buildGrid(spanOf(xyz), params);
    ASSERT_EQ(r.point_cells.size(), xyz.size() / 3);
    std::vector<std::uint64_t> counts(r.cells.size(), 0);
    for (std::size_t i = 0; i < r.point_cells.size(); ++i) {
      const std::int64_t c = r.point_cells[i];
      ASSERT_GE(c, 0);
      ++counts[static_cast<std::size_t>(c)];
      EXPECT_TRUE(r.cells[static_cast<std::size_t>(c)].first_point <= i);
    }
    for (std::size_t c = 0; c < counts.size(); ++c) EXPECT_EQ(counts[c], r.cells[c].count);
  }
}

TEST(GridOrigin, RefusesANonFiniteStart) {
  const std::vector<float> xyz = randomCloud(10, 1);
  GridParams params;
  params.origin = GridOrigin::Point;
  params.origin_point = Eigen::Vector3d(0, std::nan(""), 0);
  EXPECT_THROW(buildGrid(spanOf(xyz), params), std::invalid_argument);
}

}  // namespace
}  // namespace metricmap
