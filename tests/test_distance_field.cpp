// DistanceField against a brute-force nearest-obstacle search written in the test (2D and 3D,
// signed and unsigned, unknown as free and as occupied), its queries against finite
// differences of the interpolant and a brute-force nearest obstacle, and its builders.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "distance_reference.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/distance/distance_field.h"
#include "metricmap/distance/distance_sources.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/map_server_reader.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "temp_dir.h"

namespace metricmap {
namespace {

OccupancyBox randomBox(int dims, std::array<std::size_t, 3> shape, double p_occ, double p_unknown,
                       unsigned seed) {
  OccupancyBox box;
  box.dimensions = dims;
  box.shape = shape;
  box.resolution = 0.25;
  box.origin = Eigen::Vector3d(-1.0, 2.0, dims == 3 ? 0.5 : 0.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  box.state.resize(box.voxels());
  for (auto& s : box.state) {
    const double r = u(rng);
    s = r < p_occ ? kVoxelOccupied : (r < p_occ + p_unknown ? kVoxelUnknown : kVoxelFree);
  }
  return box;
}

void expectEqualFields(const std::vector<float>& got, const std::vector<float>& want) {
  ASSERT_EQ(got.size(), want.size());
  std::size_t bad = 0;
  for (std::size_t v = 0; v < got.size(); ++v) {
    if (std::abs(got[v] - want[v]) > 1e-6f && bad++ < 5) {
      ADD_FAILURE() << "voxel " << v << ": " << got[v] << " vs brute force " << want[v];
    }
  }
  EXPECT_EQ(bad, 0u);
}

struct Case {
  int dims;
  std::array<std::size_t, 3> shape;
  double p_occ, p_unknown, max_distance;
  bool signed_distance;
  UnknownAs unknown;
};

TEST(DistanceField, EqualsBruteForce2DAnd3D) {
  const std::vector<Case> cases = {
      {2, {37, 29, 1}, 0.02, 0.2, 2.0, false, UnknownAs::Free},
      {2, {37, 29, 1}, 0.02, 0.2, 100.0, true, UnknownAs::Free},
      {2, {31, 40, 1}, 0.05, 0.3, 1.3, false, UnknownAs::Occupied},
      {2, {31, 40, 1}, 0.3, 0.1, 3.0, true, UnknownAs::Occupied},
      {2, {1, 25, 1}, 0.05, 0.0, 10.0, false, UnknownAs::Free},
      {3, {17, 13, 11}, 0.01, 0.2, 2.0, false, UnknownAs::Free},
      {3, {17, 13, 11}, 0.01, 0.2, 100.0, true, UnknownAs::Free},
      {3, {12, 15, 9}, 0.02, 0.3, 1.1, false, UnknownAs::Occupied},
      {3, {12, 15, 9}, 0.4, 0.1, 100.0, true, UnknownAs::Occupied},
      {3, {9, 8, 7}, 0.0, 0.0, 1.0, false, UnknownAs::Free},
      {3, {9, 8, 7}, 0.0005, 0.0, 0.2, true, UnknownAs::Free},
  };
  unsigned seed = 1;
  for (const Case& c : cases) {
    for (unsigned threads : {1u, 3u}) {
      DistanceFieldParams p;
      p.max_distance = c.max_distance;
      p.signed_distance = c.signed_distance;
      p.unknown = c.unknown;
      p.threads = threads;
      const OccupancyBox box = randomBox(c.dims, c.shape, c.p_occ, c.p_unknown, seed++);
      SCOPED_TRACE(::testing::Message()
                   << "dims " << c.dims << " shape " << c.shape[0] << "x" << c.shape[1] << "x"
                   << c.shape[2] << " signed " << c.signed_distance << " max " << c.max_distance
                   << " threads " << threads);
      const std::vector<float> want = testing::bruteForceField(box, p);
      const DistanceField field(box, p);
      expectEqualFields(field.field(), want);
    }
  }
}

TEST(DistanceField, QueriesInterpolateAndGradientMatchesFiniteDifferences) {
  for (int dims : {2, 3}) {
    DistanceFieldParams p;
    p.max_distance = 1.5;
    p.signed_distance = dims == 3;
    const std::array<std::size_t, 3> shape =
        dims == 2 ? std::array<std::size_t, 3>{30, 22, 1} : std::array<std::size_t, 3>{14, 12, 10};
    const DistanceField f(randomBox(dims, shape, 0.03, 0.1, 7 + dims), p);
    const double res = f.resolution();
    // at voxel centres the interpolant is the voxel's value
    for (std::size_t i = 0; i < shape[0]; i += 3) {
      for (std::size_t j = 0; j < shape[1]; j += 2) {
        const std::size_t k = dims == 3 ? j % shape[2] : 0;
        const Eigen::Vector3d c = f.origin() + Eigen::Vector3d(i, j, k) * res;
        const DistanceQuery q = f.query(c);
        ASSERT_TRUE(q.inside);
        EXPECT_NEAR(q.distance, f.at(i, j, k), 1e-9);
      }
    }
    // the gradient is the interpolant's: central differences inside a cell
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double h = 1e-6 * res;
    int checked = 0;
    for (int n = 0; n < 400; ++n) {
      Eigen::Vector3d cell(u(rng) * (shape[0] - 1), u(rng) * (shape[1] - 1),
                           dims == 3 ? u(rng) * (shape[2] - 1) : 0.0);
      // keep away from cell faces, where the interpolant has a kink
      bool near_face = false;
      for (int a = 0; a < dims; ++a) {
        const double frac = cell[a] - std::floor(cell[a]);
        near_face = near_face || frac < 1e-3 || frac > 1 - 1e-3;
      }
      if (near_face) continue;
      const Eigen::Vector3d pt = f.origin() + cell * res;
      const DistanceQuery q = f.query(pt);
      ASSERT_TRUE(q.inside);
      for (int a = 0; a < dims; ++a) {
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e[a] = h;
        const double fd = (f.query(pt + e).distance - f.query(pt - e).distance) / (2 * h);
        EXPECT_NEAR(q.gradient[a], fd, 1e-4 * std::max(1.0, std::abs(fd))) << "axis " << a;
      }
      if (dims == 2) {
        EXPECT_EQ(q.gradient.z(), 0.0);
      }
      ++checked;
    }
    EXPECT_GT(checked, 300);
    // batched queries equal single ones; outside points are NaN
    std::vector<double> xyz = {f.origin().x() + 0.3,
                               f.origin().y() + 0.4,
                               f.origin().z(),
                               f.origin().x() - 1.0,
                               f.origin().y(),
                               f.origin().z(),
                               std::nan(""),
                               0.0,
                               0.0};
    std::vector<double> d(3), g(9);
    f.queryMany(xyz.data(), 3, d.data(), g.data());
    const DistanceQuery q0 = f.query(Eigen::Vector3d(xyz[0], xyz[1], xyz[2]));
    EXPECT_EQ(d[0], q0.distance);
    EXPECT_EQ(g[1], q0.gradient.y());
    EXPECT_TRUE(std::isnan(d[1]));
    EXPECT_TRUE(std::isnan(g[3]));
    EXPECT_TRUE(std::isnan(d[2]));
    EXPECT_FALSE(f.query(f.origin() - Eigen::Vector3d(res, 0, 0)).inside);
  }
}

TEST(DistanceField, NearestObstacleEqualsBruteForce) {
  for (int dims : {2, 3}) {
    for (UnknownAs unknown : {UnknownAs::Free, UnknownAs::Occupied}) {
      DistanceFieldParams p;
      p.max_distance = 2.0;
      p.unknown = unknown;
      const std::array<std::size_t, 3> shape =
          dims == 2 ? std::array<std::size_t, 3>{25, 21, 1} : std::array<std::size_t, 3>{12, 11, 9};
      const OccupancyBox box = randomBox(dims, shape, 0.02, 0.05, 11 + dims);
      const DistanceField f(box, p);
      const double res = f.resolution();
      std::mt19937 rng(5);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      for (int n = 0; n < 100; ++n) {
        const Eigen::Vector3d cell(u(rng) * (shape[0] - 1), u(rng) * (shape[1] - 1),
                                   dims == 3 ? u(rng) * (shape[2] - 1) : 0.0);
        const Eigen::Vector3d pt = f.origin() + cell * res;
        // brute force: every obstacle voxel, and the walls' voxels beyond the box
        double best = std::numeric_limits<double>::infinity();
        const auto consider = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
          Eigen::Vector3d d = Eigen::Vector3d(x, y, z) - cell;
          if (dims == 2) d.z() = 0;
          best = std::min(best, d.norm());
        };
        for (std::int64_t x = -1; x <= static_cast<std::int64_t>(shape[0]); ++x) {
          for (std::int64_t y = -1; y <= static_cast<std::int64_t>(shape[1]); ++y) {
            for (std::int64_t z = dims == 3 ? -1 : 0;
                 z <= (dims == 3 ? static_cast<std::int64_t>(shape[2]) : 0); ++z) {
              const bool out = x < 0 || y < 0 || z < 0 ||
                               x >= static_cast<std::int64_t>(shape[0]) ||
                               y >= static_cast<std::int64_t>(shape[1]) ||
                               z >= static_cast<std::int64_t>(shape[2]);
              if (out ? unknown == UnknownAs::Occupied : f.isObstacle(x, y, z)) consider(x, y, z);
            }
          }
        }
        // the voxel holding pt: its field value decides whether an obstacle is in reach
        const Eigen::Vector3d r = (cell.array() + 0.5).floor();
        const float at = f.at(static_cast<std::size_t>(r.x()), static_cast<std::size_t>(r.y()),
                              static_cast<std::size_t>(r.z()));
        Eigen::Vector3d o;
        const bool found = f.nearestObstacle(pt, o);
        if (at >= p.max_distance) {
          EXPECT_FALSE(found);
          continue;
        }
        ASSERT_TRUE(found);
        Eigen::Vector3d d = (o - pt) / res;
        if (dims == 2) d.z() = 0;
        EXPECT_NEAR(d.norm(), best, 1e-9);
      }
    }
  }
}

TEST(DistanceField, FromLogOddsMapEqualsBruteForceOverItsStates) {
  LogOddsParams lp;
  lp.resolution = 0.2;
  LogOddsMap map(lp);
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> coord(-9, 9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 1500; ++n) {
    const VoxelKey k{coord(rng), coord(rng) + 3, coord(rng) / 2};
    map.setLogOdds(k, u(rng) < 0.1 ? 2.0f : -1.0f);
  }
  for (bool signed_distance : {false, true}) {
    DistanceFieldParams p;
    p.max_distance = 1.0;
    p.signed_distance = signed_distance;
    const OccupancyBox box = occupancyBoxOf(map, p);
    VoxelKey lo, hi;
    ASSERT_TRUE(map.keyBounds(lo, hi));
    EXPECT_EQ(box.shape[0], static_cast<std::size_t>(hi.x - lo.x + 1));
    EXPECT_NEAR(box.origin.x(), (lo.x + 0.5) * 0.2, 1e-12);
    // states as the map reports them, voxel by voxel
    for (std::size_t i = 0; i < box.shape[0]; ++i) {
      for (std::size_t j = 0; j < box.shape[1]; ++j) {
        for (std::size_t k = 0; k < box.shape[2]; ++k) {
          const VoxelState s = map.state(VoxelKey{lo.x + static_cast<std::int64_t>(i),
                                                  lo.y + static_cast<std::int64_t>(j),
                                                  lo.z + static_cast<std::int64_t>(k)});
          const std::uint8_t want = s == VoxelState::Occupied ? kVoxelOccupied
                                    : s == VoxelState::Free   ? kVoxelFree
                                                              : kVoxelUnknown;
          ASSERT_EQ(box.state[(i * box.shape[1] + j) * box.shape[2] + k], want);
        }
      }
    }
    const DistanceField f(box, p);
    expectEqualFields(f.field(), testing::bruteForceField(box, p));
    EXPECT_EQ(f.occupiedVoxels(), map.occupiedVoxels());
    EXPECT_TRUE(f.isObserved(map.centerOf(VoxelKey{lo.x, lo.y, lo.z})) ==
                (map.state(VoxelKey{lo.x, lo.y, lo.z}) != VoxelState::Unknown));
  }
}

TEST(DistanceField, FromMapServerFilesEqualsBruteForceOverPixels) {
  TempDir dir("distance_map_server");
  MapServerImage im;
  im.width = 23;
  im.height = 17;
  im.resolution = 0.05;
  im.origin_x = -0.4;
  im.origin_y = 1.3;
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> v(0, 255);
  im.pixels.resize(23 * 17);
  for (auto& px : im.pixels) px = static_cast<std::uint8_t>(v(rng) < 20 ? 0 : v(rng));
  writeMapServer(im, mapServerFiles(dir / "m.pgm"));
  const Map2D map = loadMapServer(dir / "m.yaml");
  EXPECT_EQ(map.width, 23);
  EXPECT_EQ(map.resolution, 0.05);
  DistanceFieldParams p;
  p.max_distance = 0.4;
  const OccupancyBox box = occupancyBoxOf(map, p);
  ASSERT_EQ(box.dimensions, 2);
  // cell (i, j): column i, row height - 1 - j, classified by map_server's thresholds
  for (std::size_t i = 0; i < 23; ++i) {
    for (std::size_t j = 0; j < 17; ++j) {
      const std::uint8_t px = im.pixels[(16 - j) * 23 + i];
      const double occ = (255.0 - px) / 255.0;
      const std::uint8_t want =
          occ > 0.65 ? kVoxelOccupied : (occ < 0.196 ? kVoxelFree : kVoxelUnknown);
      ASSERT_EQ(box.state[i * 17 + j], want) << i << "," << j;
    }
  }
  EXPECT_NEAR(box.origin.x(), -0.4 + 0.025, 1e-12);
  const DistanceField f(box, p);
  expectEqualFields(f.field(), testing::bruteForceField(box, p));
  // bad YAML: one message naming the file and field
  const std::string bad =
      dir.write("bad.yaml", "image: m.pgm\nresolution: -1\norigin: [0, 0, 0]\n");
  try {
    loadMapServer(bad);
    ADD_FAILURE() << "negative resolution accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("resolution"), std::string::npos) << e.what();
  }
}

TEST(DistanceField, FromPointsEqualsBruteForce) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(-1.0f, 1.5f);
  for (int n = 0; n < 60; ++n) cloud.push_back(pcl::PointXYZ(u(rng), u(rng), u(rng) * 0.5f));
  cloud.push_back(pcl::PointXYZ(std::nanf(""), 0, 0));
  DistanceFieldParams p;
  p.max_distance = 0.6;
  const OccupancyBox box = occupancyBoxOf(cloud, 0.1, p);
  std::size_t occupied = 0;
  for (auto s : box.state) occupied += s == kVoxelOccupied;
  EXPECT_GT(occupied, 50u);
  const DistanceField f(box, p);
  expectEqualFields(f.field(), testing::bruteForceField(box, p));
  // every point's voxel is an obstacle at distance 0
  for (const auto& pt : cloud) {
    if (!std::isfinite(pt.x)) continue;
    const Eigen::Vector3d c =
        ((Eigen::Vector3d(pt.x, pt.y, pt.z) / 0.1).array().floor() + 0.5) * 0.1;
    EXPECT_NEAR(f.query(c).distance, 0.0, 1e-6);
  }
}

TEST(DistanceField, BoxBeyondTheBudgetIsRefusedBeforeAllocating) {
  const std::uint64_t before = memoryBudget();
  setMemoryBudget(std::uint64_t{64} << 20);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back(pcl::PointXYZ(0, 0, 0));
  cloud.push_back(pcl::PointXYZ(400, 400, 40));  // 2000 x 2000 x 200 voxels at 0.2 m
  DistanceFieldParams p;
  try {
    (void)occupancyBoxOf(cloud, 0.2, p);
    ADD_FAILURE() << "a box beyond the budget was accepted";
  } catch (const CapacityError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("2001 x 2001 x 201"), std::string::npos) << m;
  }
  setMemoryBudget(before);
  DistanceFieldParams nan;
  nan.max_distance = std::nan("");
  EXPECT_THROW(DistanceField(randomBox(2, {4, 4, 1}, 0.1, 0, 1), nan), std::invalid_argument);
  nan.max_distance = -1;
  EXPECT_THROW(DistanceField(randomBox(2, {4, 4, 1}, 0.1, 0, 1), nan), std::invalid_argument);
}

}  // namespace
}  // namespace metricmap
