// OccupancyGrid against brute-force recounts done with exact integer arithmetic.
#include <cmath>
#include <map>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Key = std::tuple<long long, long long, long long>;

long long floorDiv(long long a, long long b) {
  long long q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

struct Ref {
  std::uint64_t count = 0;
  double sx = 0, sy = 0, sz = 0;
};

// Points on a lattice of 1/unit (unit 1000: millimetre decimals as in the study's files).
// The reference bins the integer coordinates, so it is exact whatever float rounding does.
void checkAgainstRecount(const std::vector<std::array<long long, 3>>& lattice, long long unit,
                         long long cell_units) {
  auto cloud = std::make_shared<Cloud>();
  for (const auto& q : lattice) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(q[0]) / unit, static_cast<float>(q[1]) / unit,
                                   static_cast<float>(q[2]) / unit));
  }
  std::array<long long, 3> lo = lattice[0], hi = lattice[0];
  for (const auto& q : lattice) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], q[a]);
      hi[a] = std::max(hi[a], q[a]);
    }
  }
  std::map<Key, Ref> ref;
  for (std::size_t i = 0; i < lattice.size(); ++i) {
    const auto& q = lattice[i];
    Ref& r = ref[Key{floorDiv(q[0] - lo[0], cell_units), floorDiv(q[1] - lo[1], cell_units),
                     floorDiv(q[2] - lo[2], cell_units)}];
    ++r.count;
    r.sx += (*cloud)[i].x;
    r.sy += (*cloud)[i].y;
    r.sz += (*cloud)[i].z;
  }
  std::uint64_t total = 1;
  for (int a = 0; a < 3; ++a) total *= static_cast<std::uint64_t>((hi[a] - lo[a]) / cell_units + 1);

  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(static_cast<float>(static_cast<double>(cell_units) / unit));
  grid.setInputCloud(cloud);
  Cloud means;
  grid.filter(means);
  const GridStatistics& s = grid.getStatistics();
  EXPECT_EQ(s.total_cells, total);
  EXPECT_EQ(s.occupied_cells, ref.size());
  EXPECT_EQ(s.empty_cells, total - ref.size());
  EXPECT_EQ(s.points, lattice.size());
  EXPECT_DOUBLE_EQ(s.mean_points_per_occupied_cell,
                   static_cast<double>(lattice.size()) / static_cast<double>(ref.size()));
  ASSERT_EQ(means.size(), ref.size());
  for (const auto& [key, r] : ref) {
    const GridCell* c = grid.findCell({std::get<0>(key), std::get<1>(key), std::get<2>(key)});
    ASSERT_NE(c, nullptr) << "cell " << std::get<0>(key) << " " << std::get<1>(key) << " "
                          << std::get<2>(key) << " missing";
    EXPECT_EQ(c->count, r.count);
    EXPECT_NEAR(c->mean.x(), r.sx / r.count, 1e-9);
    EXPECT_NEAR(c->mean.y(), r.sy / r.count, 1e-9);
    EXPECT_NEAR(c->mean.z(), r.sz / r.count, 1e-9);
  }
}

std::vector<std::array<long long, 3>> randomLattice(std::size_t n, long long span, long long offset,
                                                    long long snap, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<long long> d(0, span / snap);
  std::vector<std::array<long long, 3>> out;
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back({offset + d(rng) * snap, offset / 2 + d(rng) * snap, -offset + d(rng) * snap});
  }
  return out;
}

}  // namespace

TEST(OccupancyGrid, MatchesExactRecountOnDecimalData) {
  // Millimetre decimals with many points exactly on cell boundaries (multiples of 10 mm).
  for (long long cell : {100, 250, 300, 500, 1000, 2000}) {
    SCOPED_TRACE("cell " + std::to_string(cell) + " mm");
    checkAgainstRecount(randomLattice(20000, 40000, -46552, 10, 1), 1000, cell);
    checkAgainstRecount(randomLattice(20000, 9000, 3017, 1, 2), 1000, cell);
  }
}

TEST(OccupancyGrid, MatchesExactRecountOnAWideGrid) {
  // 4 km at 1 cm: 56-bit keys, which do not pack with 15-bit positions into one word, so the
  // (key, position) pair sort runs; every point lies on a cell boundary.
  checkAgainstRecount(randomLattice(20000, 4000000, -1234567, 10, 4), 1000, 10);
  // 4 km at 10 cm: 46-bit keys packed with the positions.
  checkAgainstRecount(randomLattice(20000, 4000000, -1234567, 10, 5), 1000, 100);
}

TEST(OccupancyGrid, MatchesExactRecountOnDyadicData) {
  for (long long cell : {16, 24, 64}) {
    checkAgainstRecount(randomLattice(5000, 6400, -3200, 1, 3), 64, cell);
  }
}

TEST(OccupancyGrid, RejectsBadCellSizes) {
  OccupancyGrid<pcl::PointXYZ> grid;
  for (float bad : {0.0f, -1.0f, std::nanf(""), INFINITY, -INFINITY}) {
    EXPECT_THROW(grid.setCellSize(bad), std::invalid_argument) << bad;
  }
  EXPECT_THROW(grid.compute(), std::invalid_argument);  // no input
}

TEST(OccupancyGrid, OneKilometreAtOneCentimetre) {
  auto cloud = std::make_shared<Cloud>();
  cloud->push_back(pcl::PointXYZ(0, 0, 0));
  cloud->push_back(pcl::PointXYZ(1000, 1000, 1000));
  cloud->push_back(pcl::PointXYZ(500.005f, 0.004f, 999.999f));
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(0.01f);
  grid.setInputCloud(cloud);
  Cloud out;
  grid.filter(out);
  const std::uint64_t per_axis = 100001;
  EXPECT_EQ(grid.getStatistics().total_cells, per_axis * per_axis * per_axis);
  EXPECT_EQ(grid.getStatistics().occupied_cells, 3u);
  EXPECT_EQ(out.size(), 3u);
  EXPECT_NE(grid.findCell({100000, 100000, 100000}), nullptr);
  EXPECT_NE(grid.findCell({50000, 0, 99999}), nullptr);
}

TEST(OccupancyGrid, RefusesGridsBeyond64Bits) {
  auto cloud = std::make_shared<Cloud>();
  cloud->push_back(pcl::PointXYZ(-1e6f, -1e6f, -1e6f));
  cloud->push_back(pcl::PointXYZ(1e6f, 1e6f, 1e6f));
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(1e-4f);  // 2e10 cells per axis: 8e30 in all
  grid.setInputCloud(cloud);
  EXPECT_THROW(grid.compute(), CapacityError);
  grid.setOrigin(GridOrigin::WorldAligned);
  EXPECT_THROW(grid.compute(), CapacityError);
}

TEST(OccupancyGrid, SkipsNonFinitePointsAndHonoursIndices) {
  auto cloud = std::make_shared<Cloud>();
  cloud->push_back(pcl::PointXYZ(0.1f, 0.1f, 0.1f));
  cloud->push_back(pcl::PointXYZ(std::nanf(""), 0, 0));
  cloud->push_back(pcl::PointXYZ(0.3f, 0.2f, 0.1f));
  cloud->push_back(pcl::PointXYZ(5.5f, 0.1f, INFINITY));
  cloud->push_back(pcl::PointXYZ(2.5f, 0.1f, 0.1f));
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(1.0f);
  grid.setInputCloud(cloud);
  grid.compute();
  EXPECT_EQ(grid.getStatistics().points, 3u);
  EXPECT_EQ(grid.getStatistics().skipped_points, 2u);
  EXPECT_EQ(grid.getStatistics().occupied_cells, 2u);
  EXPECT_EQ(grid.getStatistics().total_cells, 3u);  // x extent 2.4 -> 3 cells, y and z 1

  auto indices = std::make_shared<pcl::Indices>(pcl::Indices{0, 2});
  grid.setIndices(indices);
  Cloud out;
  grid.filter(out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_FLOAT_EQ(out[0].x, 0.2f);
  EXPECT_FLOAT_EQ(out[0].y, 0.15f);
}

TEST(OccupancyGrid, KeepsOtherFieldsOfTheFirstPoint) {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZRGB>>();
  pcl::PointXYZRGB a(0.1f, 0.0f, 0.0f, 10, 20, 30), b(0.3f, 0.0f, 0.0f, 40, 50, 60);
  cloud->push_back(a);
  cloud->push_back(b);
  OccupancyGrid<pcl::PointXYZRGB> grid;
  grid.setCellSize(1.0f);
  grid.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZRGB> out;
  grid.filter(out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_FLOAT_EQ(out[0].x, 0.2f);
  EXPECT_EQ(out[0].r, 10);
  EXPECT_EQ(out[0].b, 30);
}

TEST(OccupancyGrid, FilterWithoutInputThrowsAsComputeDoes) {
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(0.5f);
  pcl::PointCloud<pcl::PointXYZ> out;
  out.push_back(pcl::PointXYZ(1, 2, 3));
  EXPECT_THROW(grid.compute(), std::invalid_argument);
  EXPECT_THROW(grid.filter(out), std::invalid_argument);  // pcl::Filter returns quietly
  EXPECT_EQ(out.size(), 1u);                              // and leaves the output as it was
}

}  // namespace metricmap
