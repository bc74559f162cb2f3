// LogOddsMap voxels through byte buffers: maps of frame ranges, exchanged by owner and merged,
// equal the map of all frames up to float rounding where no clamping is hit; clamping is per
// part (documented in log_odds_transfer.h); corrupt buffers are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "metricmap/common/tile_owner.h"
#include "metricmap/exceptions.h"
#include "metricmap/occupancy/log_odds_transfer.h"
#include "occupancy_scans.h"

namespace metricmap {
namespace {

LogOddsParams wideClamps() {
  LogOddsParams p;
  p.resolution = 0.2;
  p.max_range = 30.0;
  p.clamp_min = 1e-6;  // never reached by six frames: no clamping
  p.clamp_max = 1.0 - 1e-6;
  return p;
}

TEST(LogOddsTransfer, FrameRangesExchangedByOwnerEqualOneProcess) {
  const LogOddsParams p = wideClamps();
  std::vector<test::WorldScan> scans;
  for (std::size_t f = 0; f < 6; ++f) scans.push_back(test::subsample(test::kittiWorldScan(f), 4));
  LogOddsMap all(p);
  for (const auto& s : scans) all.insertScan(s.points, s.origin);

  const unsigned ranks = 3;  // frames {0,1}, {2,3}, {4,5}
  std::vector<std::vector<std::vector<std::uint8_t>>> sent(ranks);
  for (unsigned r = 0; r < ranks; ++r) {
    LogOddsMap part(p);
    for (std::size_t f = 2 * r; f < 2 * r + 2; ++f)
      part.insertScan(scans[f].points, scans[f].origin);
    sent[r] = serializeLogOddsByOwner(part, ranks);
  }
  LogOddsMap gathered(p);
  std::size_t owned_total = 0;
  for (unsigned o = 0; o < ranks; ++o) {
    LogOddsMap owned(p);
    for (unsigned r = 0; r < ranks; ++r)
      owned.merge(deserializeLogOdds(sent[r][o].data(), sent[r][o].size(), "buffer"));
    owned.forEachKnown(
        [&](const VoxelKey& k, float) { ASSERT_EQ(tileOwner(k.x, k.y, k.z, ranks), o); });
    owned_total += owned.knownVoxels();
    const auto bytes = serializeLogOdds(owned);
    gathered.merge(deserializeLogOdds(bytes.data(), bytes.size(), "owner"));
  }
  ASSERT_EQ(owned_total, all.knownVoxels());  // owners hold disjoint voxels
  ASSERT_EQ(gathered.knownVoxels(), all.knownVoxels());
  EXPECT_EQ(gathered.occupiedVoxels(), all.occupiedVoxels());
  std::size_t exact = 0, close = 0, several = 0;
  all.forEachKnown([&](const VoxelKey& k, float l) {
    const std::optional<float> m = gathered.logOdds(k);
    ASSERT_TRUE(m.has_value());
    exact += *m == l ? 1 : 0;
    close += std::abs(*m - l) <= 4e-6f ? 1 : 0;  // a few ulp of sums below ~10
    several += (l != all.hitLogOdds() && l != all.missLogOdds()) ? 1 : 0;
    EXPECT_EQ(gathered.isOccupied(*m), all.isOccupied(l));
  });
  EXPECT_EQ(close, all.knownVoxels());
  EXPECT_GT(several, 10000u);  // voxels seen by several frames: the sums are really tested
  EXPECT_GT(exact, all.knownVoxels() * 9 / 10);  // most sums are even bit-identical
}

// A rank keeps its own tiles in memory (mergeOwnedBlocks) instead of sending them to itself:
// the same voxels and the same bits as merging its buffer, and its buffer is left empty.
TEST(LogOddsTransfer, OwnTilesKeptInMemoryEqualTheirBuffer) {
  const LogOddsParams p = wideClamps();
  LogOddsMap first(p), second(p);
  for (std::size_t f = 0; f < 3; ++f) {
    const test::WorldScan s = test::subsample(test::kittiWorldScan(f), 4);
    first.insertScan(s.points, s.origin);
  }
  const test::WorldScan s = test::subsample(test::kittiWorldScan(3), 4);
  second.insertScan(s.points, s.origin);
  const unsigned parts = 3;
  std::size_t total = 0;
  for (unsigned part = 0; part < parts; ++part) {
    const auto all = serializeLogOddsByOwner(first, parts);
    const auto kept = serializeLogOddsByOwner(first, parts, part);
    for (unsigned k = 0; k < parts; ++k) {
      if (k == part) {
        EXPECT_EQ(deserializeLogOdds(kept[k].data(), kept[k].size(), "kept").knownVoxels(), 0u);
      } else {
        EXPECT_EQ(kept[k], all[k]);
      }
    }
    const auto second_bytes = serializeLogOddsByOwner(second, parts);
    LogOddsMap by_buffer(p), in_memory(p);  // the second map's part first, then the first's
    mergeSerializedLogOdds(by_buffer, second_bytes[part].data(), second_bytes[part].size(), "b");
    mergeSerializedLogOdds(in_memory, second_bytes[part].data(), second_bytes[part].size(), "b");
    mergeSerializedLogOdds(by_buffer, all[part].data(), all[part].size(), "a");
    mergeOwnedBlocks(in_memory, first, part, parts);
    ASSERT_EQ(in_memory.knownVoxels(), by_buffer.knownVoxels());
    total += in_memory.knownVoxels();
    by_buffer.forEachKnown([&](const VoxelKey& k, float l) {
      const std::optional<float> m = in_memory.logOdds(k);
      ASSERT_TRUE(m.has_value());
      EXPECT_EQ(std::memcmp(&*m, &l, sizeof l), 0);
    });
  }
  EXPECT_GT(total, first.knownVoxels());  // the parts together cover both maps
}

// One voxel: part A misses it five times (its sum passes clamp_min and is clamped there), part
// B hits it ten times (clamped at clamp_max). One process, A then B, ends at clamp_max; the
// merge adds the clamped parts: clamp_min + clamp_max.
TEST(LogOddsTransfer, ClampingIsPerPart) {
  LogOddsParams p;  // OctoMap's defaults: clamping at 0.1192 and 0.971
  p.resolution = 1.0;
  const Eigen::Vector3f origin(0.5f, 0.5f, 0.5f);
  pcl::PointCloud<pcl::PointXYZ> through, at;
  through.push_back({10.5f, 0.5f, 0.5f});  // crosses voxel (5, 0, 0)
  at.push_back({5.5f, 0.5f, 0.5f});        // ends in it
  LogOddsMap one(p), a(p), b(p);
  for (int i = 0; i < 5; ++i) {
    one.insertScan(through, origin);
    a.insertScan(through, origin);
  }
  for (int i = 0; i < 10; ++i) {
    one.insertScan(at, origin);
    b.insertScan(at, origin);
  }
  const VoxelKey v{5, 0, 0};
  EXPECT_EQ(*a.logOdds(v), a.clampMinLogOdds());
  EXPECT_EQ(*b.logOdds(v), b.clampMaxLogOdds());
  EXPECT_EQ(*one.logOdds(v), one.clampMaxLogOdds());
  const auto bytes = serializeLogOdds(b);
  a.merge(deserializeLogOdds(bytes.data(), bytes.size(), "b"));
  EXPECT_EQ(*a.logOdds(v), a.clampMinLogOdds() + a.clampMaxLogOdds());
  EXPECT_LT(*a.logOdds(v), one.clampMaxLogOdds() - 1.0f);
}

// Merging a buffer straight into a map equals deserialising it and merging the map.
TEST(LogOddsTransfer, MergeSerializedEqualsMergeOfTheMap) {
  const LogOddsParams p = wideClamps();
  LogOddsMap a(p), b(p);
  for (std::size_t f = 0; f < 2; ++f) {
    const test::WorldScan s = test::subsample(test::kittiWorldScan(f), 8);
    (f == 0 ? a : b).insertScan(s.points, s.origin);
  }
  LogOddsMap c = a;
  const LogOddsMap before = a;
  const auto bytes = serializeLogOdds(b);
  LogOddsMap direct = a;
  mergeSerializedLogOdds(direct, bytes.data(), bytes.size(), "b");
  a.merge(deserializeLogOdds(bytes.data(), bytes.size(), "b"));
  ASSERT_EQ(direct.knownVoxels(), a.knownVoxels());
  a.forEachKnown([&](const VoxelKey& k, float l) { EXPECT_EQ(*direct.logOdds(k), l); });
  // a corrupt buffer leaves the map unchanged; other parameters are refused
  std::vector<std::uint8_t> bad = bytes;
  bad[bad.size() - 1] = 0xff;  // last log-odds: NaN
  bad[bad.size() - 2] = 0xff;
  EXPECT_THROW(mergeSerializedLogOdds(c, bad.data(), bad.size(), "x"), InputError);
  ASSERT_EQ(c.knownVoxels(), before.knownVoxels());
  before.forEachKnown([&](const VoxelKey& k, float l) { EXPECT_EQ(*c.logOdds(k), l); });
  LogOddsParams q = p;
  q.resolution = 0.3;
  LogOddsMap other(q);
  EXPECT_THROW(mergeSerializedLogOdds(other, bytes.data(), bytes.size(), "x"), InputError);
}

TEST(LogOddsTransfer, CorruptBuffersAreRefused) {
  const test::WorldScan s = test::subsample(test::kittiWorldScan(0), 50);
  LogOddsMap map(wideClamps());
  map.insertScan(s.points, s.origin);
  std::vector<std::uint8_t> good = serializeLogOdds(map);
  ASSERT_GT(map.knownVoxels(), 100u);
  const LogOddsMap back = deserializeLogOdds(good.data(), good.size(), "x");
  EXPECT_EQ(back.knownVoxels(), map.knownVoxels());
  map.forEachKnown([&](const VoxelKey& k, float l) { EXPECT_EQ(*back.logOdds(k), l); });
  EXPECT_EQ(back.params().max_range, 30.0);

  const std::size_t header = 8 + 7 * 8 + 8;
  for (std::size_t n = 0; n < header + 300; ++n)
    EXPECT_THROW(deserializeLogOdds(good.data(), n, "x"), InputError) << n;
  EXPECT_THROW(deserializeLogOdds(good.data(), good.size() - 1, "x"), InputError);
  auto refused = [&](std::vector<std::uint8_t> b, const char* why) {
    try {
      deserializeLogOdds(b.data(), b.size(), "rank 1's voxels");
      ADD_FAILURE() << why << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("rank 1's voxels"), std::string::npos);
    }
  };
  std::vector<std::uint8_t> b = good;
  b[0] ^= 1;
  refused(b, "bad magic");
  b = good;
  b[4] = 9;
  refused(b, "another version");
  b = good;
  const double bad_resolution = -1.0;
  std::memcpy(b.data() + 8, &bad_resolution, 8);
  refused(b, "negative resolution");
  b = good;
  b[header + 7] |= 0x80;  // key's top bit
  refused(b, "key outside the key space");
  b = good;
  const float inf = INFINITY;
  std::memcpy(b.data() + header + 72, &inf, 4);  // first block's first log-odds
  refused(b, "infinite log-odds");
  b = good;
  std::fill(b.begin() + header + 8, b.begin() + header + 72, 0);
  refused(b, "a block without known voxels");
  // one voxel's block, twice
  LogOddsMap one(wideClamps());
  one.setLogOdds({3, 4, 5}, 0.5f);
  b = serializeLogOdds(one);
  ASSERT_EQ(b.size(), header + 72 + 4);
  b.insert(b.end(), b.begin() + header, b.end());
  const std::uint64_t two = 2;
  std::memcpy(b.data() + header - 8, &two, 8);
  refused(b, "duplicate voxel");
}

}  // namespace
}  // namespace metricmap
