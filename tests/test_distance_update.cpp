// Incremental updates of a distance field after log-odds changes equal, voxel for voxel, a
// field computed from scratch over the same box; and the nav2 inflation costmap against the
// inflation layer's formula on a hand-made map.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "distance_reference.h"
#include "metricmap/distance/distance_field.h"
#include "metricmap/distance/distance_sources.h"
#include "metricmap/distance/inflation_costmap.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/map_server_reader.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "temp_dir.h"

namespace metricmap {
namespace {

void randomVoxels(LogOddsMap& map, std::mt19937& rng, int count, double p_occ) {
  std::uniform_int_distribution<int> c(-12, 12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < count; ++n) {
    map.setLogOdds(VoxelKey{c(rng), c(rng), c(rng) / 2}, u(rng) < p_occ ? 1.5f : -1.2f);
  }
}

TEST(DistanceUpdate, IncrementalEqualsRecomputeVoxelForVoxel) {
  for (bool signed_distance : {false, true}) {
    for (UnknownAs unknown : {UnknownAs::Free, UnknownAs::Occupied}) {
      for (bool incremental : {true, false}) {
        LogOddsParams lp;
        lp.resolution = 0.1;
        LogOddsMap map(lp);
        std::mt19937 rng(17);
        randomVoxels(map, rng, 3000, 0.05);
        DistanceFieldParams p;
        p.max_distance = 0.5;
        p.signed_distance = signed_distance;
        p.unknown = unknown;
        p.incremental = incremental;
        p.threads = 2;
        const OccupancyBox first = occupancyBoxOf(map, p);
        const KeyBox box{first.min_key, first.shape};
        DistanceField field(first, p);
        std::size_t full_lines = 0, changed = 0;
        for (int round = 0; round < 4; ++round) {
          // a few changes: new voxels, flips both ways, some outside the box
          randomVoxels(map, rng, round == 0 ? 3 : 40, 0.3);
          map.setLogOdds(VoxelKey{40, 0, 0}, 2.0f);
          const DistanceUpdateReport r = field.update(map);
          const DistanceField fresh(occupancyBoxOf(map, p, box), p);
          SCOPED_TRACE(::testing::Message() << "signed " << signed_distance << " unknown occupied "
                                            << (unknown == UnknownAs::Occupied) << " incremental "
                                            << incremental << " round " << round);
          ASSERT_EQ(field.states(), fresh.states());
          ASSERT_EQ(field.field(), fresh.field());  // exact, every voxel
          EXPECT_EQ(r.full, !incremental && r.changed_voxels > 0);
          changed += r.changed_voxels;
          EXPECT_GE(r.outside_voxels, 1u);
          if (round == 0) full_lines = r.lines;
        }
        EXPECT_GT(changed, 10u);
        // the brute force agrees too
        EXPECT_EQ(field.field(), testing::bruteForceField(occupancyBoxOf(map, p, box), p));
        if (incremental) {
          // three changed voxels reach few lines of the whole box's
          const auto& s = first.shape;
          const std::size_t all =
              (s[0] * s[1] + s[0] * s[2] + s[1] * s[2]) * (signed_distance ? 2 : 1);
          EXPECT_LT(full_lines, all / 4) << full_lines << " of " << all;
        }
      }
    }
  }
}

// Long lines and a short reach: an update recomputes only spans of each line (chunks of
// several voxels widened by the reach), including spans at the box's walls; still equal to a
// field computed anew, voxel for voxel.
TEST(DistanceUpdate, SpansOfLongLinesEqualRecompute) {
  for (bool signed_distance : {false, true}) {
    for (UnknownAs unknown : {UnknownAs::Free, UnknownAs::Occupied}) {
      LogOddsParams lp;
      lp.resolution = 0.1;
      LogOddsMap map(lp);
      std::mt19937 rng(5);
      std::uniform_int_distribution<int> x(-160, 160), y(-90, 90), z(0, 7);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      auto scatter = [&](int count, double p_occ) {
        for (int n = 0; n < count; ++n)
          map.setLogOdds(VoxelKey{x(rng), y(rng), z(rng)}, u(rng) < p_occ ? 1.5f : -1.2f);
      };
      scatter(20000, 0.02);
      for (int a = -160; a <= 160; ++a) map.setLogOdds(VoxelKey{a, 0, 3}, -1.2f);  // the whole span
      DistanceFieldParams p;
      p.max_distance = 0.35;  // a reach of 4 voxels over lines of 321 and 181
      p.signed_distance = signed_distance;
      p.unknown = unknown;
      p.incremental = true;
      p.threads = 2;
      const OccupancyBox first = occupancyBoxOf(map, p);
      ASSERT_GE(first.shape[0], 300u);
      const KeyBox box{first.min_key, first.shape};
      DistanceField field(first, p);
      for (int round = 0; round < 3; ++round) {
        scatter(round == 0 ? 5 : 300, 0.4);
        // obstacles at both ends of a line: spans that reach the walls
        map.setLogOdds(VoxelKey{-160, 0, 3}, round % 2 ? -1.2f : 1.5f);
        map.setLogOdds(VoxelKey{160, 0, 3}, round % 2 ? 1.5f : -1.2f);
        const DistanceUpdateReport r = field.update(map);
        const DistanceField fresh(occupancyBoxOf(map, p, box), p);
        SCOPED_TRACE(::testing::Message()
                     << "signed " << signed_distance << " unknown occupied "
                     << (unknown == UnknownAs::Occupied) << " round " << round);
        EXPECT_GT(r.changed_voxels, 0u);
        ASSERT_EQ(field.field(), fresh.field());  // exact, every voxel
      }
    }
  }
}

// nav2_costmap_2d InflationLayer::computeCost, written out: distance in cells.
std::uint8_t nav2Cost(double cells, double res, double inscribed, double scaling) {
  if (cells == 0) return 254;
  if (cells * res <= inscribed) return 253;
  const double factor = std::exp(-1.0 * scaling * (cells * res - inscribed));
  return static_cast<std::uint8_t>((253 - 1) * factor);
}

TEST(InflationCostmap, MatchesNav2sFormulaOnAHandMadeMap) {
  // 40 x 30 cells at 5 cm: a wall, a pillar, an unknown patch, free elsewhere
  const int w = 40, h = 30;
  MapServerImage im;
  im.width = w;
  im.height = h;
  im.resolution = 0.05;
  im.origin_x = -1.0;
  im.origin_y = 0.5;
  im.pixels.assign(w * h, kMapFree);
  const auto set = [&](int i, int j, std::uint8_t v) { im.pixels[(h - 1 - j) * w + i] = v; };
  for (int j = 5; j < 25; ++j) set(10, j, kMapOccupied);
  set(30, 15, kMapOccupied);
  set(31, 15, kMapOccupied);
  for (int i = 20; i < 26; ++i) {
    for (int j = 0; j < 8; ++j) set(i, j, kMapUnknown);
  }
  set(11, 24, kMapUnknown);  // unknown next to the wall: takes its cost, 253
  MapServerYaml yaml;        // map_server's defaults, trinary
  yaml.resolution = im.resolution;
  yaml.origin_x = im.origin_x;
  yaml.origin_y = im.origin_y;
  const Map2D map = mapFromGrey(im.pixels, w, h, yaml);
  InflationParams ip;
  ip.inscribed_radius = 0.12;
  ip.inflation_radius = 0.4;
  ip.cost_scaling_factor = 6.0;
  DistanceFieldParams p;
  p.max_distance = inflationReach(im.resolution, ip);
  const DistanceField field(occupancyBoxOf(map, p), p);
  const MapServerImage cost = inflationCostmap(field, ip);
  ASSERT_EQ(cost.width, w);
  ASSERT_EQ(cost.height, h);
  EXPECT_EQ(cost.mode, MapServerMode::Raw);
  EXPECT_DOUBLE_EQ(cost.origin_x, im.origin_x);
  const double reach = std::ceil(ip.inflation_radius / im.resolution);
  int lethal = 0, inscribed = 0, unknown = 0, graded = 0;
  for (int i = 0; i < w; ++i) {
    for (int j = 0; j < h; ++j) {
      double best = 1e9;  // cells to the nearest lethal cell, by brute force
      for (int x = 0; x < w; ++x) {
        for (int y = 0; y < h; ++y) {
          if (im.pixels[(h - 1 - y) * w + x] == kMapOccupied)
            best = std::min(best, std::hypot(x - i, y - j));
        }
      }
      std::uint8_t want = best <= reach ? nav2Cost(best, im.resolution, 0.12, 6.0) : 0;
      if (im.pixels[(h - 1 - j) * w + i] == kMapUnknown && want < 253) want = 255;
      const std::uint8_t got = cost.pixels[(h - 1 - j) * w + i];
      ASSERT_EQ(static_cast<int>(got), static_cast<int>(want)) << "cell " << i << "," << j;
      lethal += got == 254;
      inscribed += got == 253;
      unknown += got == 255;
      graded += got > 0 && got < 253;
    }
  }
  EXPECT_EQ(lethal, 22);
  EXPECT_EQ(cost.pixels[(h - 1 - 24) * w + 11], kCostInscribed);
  EXPECT_GT(inscribed, 40);
  EXPECT_EQ(unknown, 48);
  EXPECT_GT(graded, 100);
  // written and read back as a map_server map in raw mode
  TempDir dir("costmap");
  writeMapServer(cost, mapServerFiles(dir / "cost.pgm"));
  const Map2D back = loadMapServer(dir / "cost.yaml");  // raw: values 0..100, others unknown
  ASSERT_EQ(back.cells.size(), cost.pixels.size());
  for (int i = 0; i < w; ++i) {
    for (int j = 0; j < h; ++j) {
      const std::uint8_t v = cost.pixels[(h - 1 - j) * w + i];
      ASSERT_EQ(back.at(i, j), v <= 100 ? static_cast<std::int8_t>(v) : kCellUnknown);
    }
  }
  // a field too short for the inflation radius is refused
  DistanceFieldParams shortp;
  shortp.max_distance = 0.2;
  EXPECT_THROW(inflationCostmap(DistanceField(occupancyBoxOf(map, shortp), shortp), ip),
               std::invalid_argument);
}

}  // namespace
}  // namespace metricmap
