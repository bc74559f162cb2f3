// The eight-lane AVX-512 and four-lane AVX2 walks mark the same voxels as the two-beam SSE2
// walk, bit for bit, on real KITTI scans at several resolutions and max ranges (where the CPU
// has AVX-512F / AVX2; elsewhere the runs fall back to a narrower walk and the test still checks
// the plumbing). The portable walk
// (RayPath::Portable, forced here on x86) marks the same voxels as both, block for block, on random
// and degenerate beams and on real scans inserted into a LogOddsMap (on CPUs without the SIMD walks
// both runs take the portable walk).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <utility>

#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/ray_kernel.h"
#include "occupancy_scans.h"

namespace metricmap {
namespace {

using Words = std::pair<std::vector<std::uint64_t>, std::vector<std::uint64_t>>;

std::map<std::uint64_t, Words> cast(const test::WorldScan& scan, double res, double max_range,
                                    int lanes, detail::RayCastCounts& counts) {
  detail::RayCastInput in;
  in.xyz = &scan.points[0].x;
  in.stride_bytes = sizeof(pcl::PointXYZ);
  in.count = scan.points.size();
  for (int i = 0; i < 3; ++i) in.origin[i] = scan.origin[i];
  in.resolution = res;
  in.max_range = max_range;
  in.lanes = lanes;
  detail::ScanUpdate out;
  counts = detail::castRays(in, out);
  std::map<std::uint64_t, Words> blocks;
  for (const detail::ScanBlock& b : out.blocks) {
    Words& w = blocks[b.key];
    w.first.assign(std::begin(b.free), std::end(b.free));
    w.second.assign(std::begin(b.hit), std::end(b.hit));
  }
  return blocks;
}

TEST(RayKernel, EightAndFourLaneWalksMarkTheSameVoxelsAsTheTwoBeamWalk) {
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t frame : {0u, 3u}) {
    test::WorldScan scan = test::kittiWorldScan(frame);
    // a few beams that end in the origin's voxel, or exactly on voxel faces
    for (const Eigen::Vector3f& d :
         {Eigen::Vector3f(0.01f, 0.01f, 0.0f), Eigen::Vector3f(2.0f, 0.0f, 0.0f),
          Eigen::Vector3f(0.0f, -4.0f, 0.0f), Eigen::Vector3f(0.0f, 0.0f, 1.0f)}) {
      const Eigen::Vector3f p = scan.origin + d;
      scan.points.push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
    }
    for (const auto& [res, range] :
         {std::pair<double, double>{0.2, 50.0}, {0.1, 50.0}, {0.35, inf}, {0.05, 10.0}}) {
      SCOPED_TRACE(testing::Message() << "frame " << frame << " res " << res << " range " << range);
      detail::RayCastCounts b;
      const auto plain = cast(scan, res, range, 2, b);
      for (int lanes : {4, 8}) {
        SCOPED_TRACE(testing::Message() << lanes << " lanes");
        detail::RayCastCounts a;
        const auto simd = cast(scan, res, range, lanes, a);
        EXPECT_EQ(a.beams, b.beams);
        EXPECT_EQ(a.cut, b.cut);
        ASSERT_EQ(simd.size(), plain.size());
        std::size_t differ = 0, free_bits = 0;
        for (const auto& [key, words] : plain) {
          const auto it = simd.find(key);
          ASSERT_NE(it, simd.end());
          differ += it->second != words ? 1 : 0;
          for (std::uint64_t w : words.first)
            free_bits += static_cast<std::size_t>(__builtin_popcountll(w));
        }
        EXPECT_EQ(differ, 0u);
        EXPECT_GT(free_bits, 10000u);  // a real walk
      }
    }
  }
}

// Beams through voxel corners and edges: the origin at a voxel's centre, ends at whole-voxel
// offsets with two or three equal components, so the crossing parameters tie at every corner.
TEST(RayKernel, EightAndFourLaneWalksBreakTiesAsTheTwoBeamWalk) {
  const double res = 0.2;
  test::WorldScan scan;
  scan.origin = Eigen::Vector3f(0.1f, 0.1f, 0.1f);
  for (int a = -6; a <= 6; ++a) {
    for (int b = -6; b <= 6; ++b) {
      for (int c = -6; c <= 6; ++c) {
        const bool tie =
            std::abs(a) == std::abs(b) || std::abs(b) == std::abs(c) || std::abs(a) == std::abs(c);
        if (!tie) continue;
        scan.points.push_back(pcl::PointXYZ(0.1f + 0.2f * static_cast<float>(a * 5),
                                            0.1f + 0.2f * static_cast<float>(b * 5),
                                            0.1f + 0.2f * static_cast<float>(c * 5)));
      }
    }
  }
  detail::RayCastCounts b;
  const auto plain = cast(scan, res, 100.0, 2, b);
  EXPECT_GT(b.beams, 500u);
  for (int lanes : {4, 8}) {
    SCOPED_TRACE(testing::Message() << lanes << " lanes");
    detail::RayCastCounts a;
    const auto simd = cast(scan, res, 100.0, lanes, a);
    ASSERT_EQ(simd.size(), plain.size());
    std::size_t differ = 0;
    for (const auto& [key, words] : plain) {
      const auto it = simd.find(key);
      ASSERT_NE(it, simd.end());
      differ += it->second != words ? 1 : 0;
    }
    EXPECT_EQ(differ, 0u);
  }
}

// --- the portable walk against the SIMD walks ---

// One cast's result in the order castRays left it: per block its key, free words and hit words.
struct Cast {
  std::vector<std::uint64_t> words;
  std::size_t blocks = 0;
  detail::RayCastCounts counts;
  bool dense = false;  // the walk used the scan's bit box (else the per-block fallback)
};

Cast castWith(detail::RayPath path, int lanes, const test::WorldScan& scan, double res,
              double max_range) {
  const detail::ScopedRayPath forced(path);
  detail::RayCastInput in;
  in.xyz = &scan.points[0].x;
  in.stride_bytes = sizeof(pcl::PointXYZ);
  in.count = scan.points.size();
  for (int i = 0; i < 3; ++i) in.origin[i] = scan.origin[i];
  in.resolution = res;
  in.max_range = max_range;
  in.lanes = lanes;
  detail::ScanUpdate out;
  Cast c;
  c.counts = detail::castRays(in, out);
  c.dense = !out.dense.empty();
  c.blocks = out.blocks.size();
  // in key order: the walks may create the scan's blocks in different orders (the map takes
  // them in key order)
  std::vector<detail::ScanBlock> blocks = out.blocks;
  std::sort(blocks.begin(), blocks.end(),
            [](const detail::ScanBlock& a, const detail::ScanBlock& b) { return a.key < b.key; });
  for (const detail::ScanBlock& b : blocks) {
    c.words.push_back(b.key);
    c.words.insert(c.words.end(), std::begin(b.free), std::end(b.free));
    c.words.insert(c.words.end(), std::begin(b.hit), std::end(b.hit));
  }
  return c;
}

testing::AssertionResult sameCast(const Cast& a, const Cast& b) {
  std::ostringstream why;
  if (a.counts.beams != b.counts.beams || a.counts.cut != b.counts.cut ||
      a.counts.non_finite != b.counts.non_finite)
    why << "counts differ; ";
  if (a.dense != b.dense) why << "one walk used the bit box, the other not; ";
  if (a.blocks != b.blocks) why << a.blocks << " blocks against " << b.blocks << "; ";
  constexpr std::size_t kPerBlock = 1 + 2 * detail::kBlockWords;
  const std::size_t n = std::min(a.words.size(), b.words.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (a.words[i] == b.words[i]) continue;
    why << "block " << i / kPerBlock << " differs first at word " << i % kPerBlock
        << " (0: key, then free, then hit words)";
    break;
  }
  if (why.str().empty()) return testing::AssertionSuccess();
  return testing::AssertionFailure() << why.str();
}

std::size_t freeBits(const Cast& c) {
  constexpr std::size_t kPerBlock = 1 + 2 * detail::kBlockWords;
  std::size_t n = 0;
  for (std::size_t i = 0; i < c.words.size(); ++i) {
    const std::size_t w = i % kPerBlock;
    if (w >= 1 && w <= static_cast<std::size_t>(detail::kBlockWords))
      n += static_cast<std::size_t>(__builtin_popcountll(c.words[i]));
  }
  return n;
}

pcl::PointXYZ toPoint(const Eigen::Vector3f& p) { return {p.x(), p.y(), p.z()}; }

// Beams from `origin`: random directions and lengths up to `reach`; along the 26 axis and
// diagonal directions (crossings tie on voxel edges and corners when the origin is on a
// voxel's centre or corner), some exactly 7.5 and 20 m long (the max ranges tried); ends on whole
// multiples of the resolution (voxel faces, edges, corners) in all three or one coordinate;
// zero-length beams, beams ending in the origin's voxel; non-finite points.
test::WorldScan degenerateRays(std::uint32_t seed, const Eigen::Vector3f& origin, double res,
                               float reach, int random_beams) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), length(0.0f, reach);
  const int cells = static_cast<int>(reach / static_cast<float>(res) / 2.0f);
  std::uniform_int_distribution<int> cell(-cells, cells);
  const auto face = [&](float o) {
    return static_cast<float>(std::floor(o / res) + cell(rng)) * static_cast<float>(res);
  };
  test::WorldScan s;
  s.origin = origin;
  for (int i = 0; i < random_beams; ++i) {
    const Eigen::Vector3f d(unit(rng), unit(rng), unit(rng));
    if (d.norm() < 1e-3f) continue;
    s.points.push_back(toPoint(origin + d.normalized() * length(rng)));
  }
  for (int a = -1; a <= 1; ++a) {
    for (int b = -1; b <= 1; ++b) {
      for (int c = -1; c <= 1; ++c) {
        if (a == 0 && b == 0 && c == 0) continue;
        const Eigen::Vector3f d(static_cast<float>(a), static_cast<float>(b),
                                static_cast<float>(c));
        for (float l : {7.5f, std::min(20.0f, reach), length(rng), length(rng),
                        static_cast<float>(res) * static_cast<float>(cell(rng))})
          s.points.push_back(toPoint(origin + d * l));
      }
    }
  }
  for (int i = 0; i < random_beams / 2; ++i)
    s.points.push_back(toPoint({face(origin.x()), face(origin.y()), face(origin.z())}));
  for (int i = 0; i < random_beams / 2; ++i) {
    Eigen::Vector3f p = origin + Eigen::Vector3f(unit(rng), unit(rng), unit(rng)) * reach * 0.5f;
    const int axis = i % 3;
    p[axis] = face(origin[axis]);
    s.points.push_back(toPoint(p));
  }
  for (int i = 0; i < 20; ++i) s.points.push_back(toPoint(origin));
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3f d(unit(rng), unit(rng), unit(rng));
    s.points.push_back(toPoint(origin + d * static_cast<float>(res) * 0.5f));
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  s.points.push_back(pcl::PointXYZ(nan, origin.y(), origin.z()));
  return s;
}

TEST(RayKernel, RayPathIsSetAndRestoredByTheGuard) {
  const detail::RayPath start = detail::rayPath();
#if defined(__SSE2__) && defined(__x86_64__)
  // the SIMD walks are compiled here and taken by default: the comparisons below are not
  // between the portable walk and itself
  EXPECT_EQ(start, detail::RayPath::Simd);
#else
  EXPECT_EQ(start, detail::RayPath::Portable);
#endif
  {
    const detail::ScopedRayPath portable(detail::RayPath::Portable);
    EXPECT_EQ(detail::rayPath(), detail::RayPath::Portable);
    {
      const detail::ScopedRayPath simd(detail::RayPath::Simd);
      EXPECT_EQ(detail::rayPath(), start);
    }
    EXPECT_EQ(detail::rayPath(), detail::RayPath::Portable);
  }
  EXPECT_EQ(detail::rayPath(), start);
}

TEST(RayKernel, PortableWalkMarksTheSameVoxelsAsTheSimdWalksOnDegenerateRays) {
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    double res;
    Eigen::Vector3f origin;
    float reach;
    const char* what;
  };
  const Case cases[] = {
      {0.1, {-3.37f, 12.91f, -1.73f}, 40.0f, "negative coordinates, 0.1 m"},
      {0.25, {-2.0f, 1.0f, -0.5f}, 40.0f, "origin on a voxel corner"},
      {0.25, {0.125f, -0.375f, 0.625f}, 40.0f, "origin on a voxel centre"},
      {0.2, {0.0f, 0.0f, 0.0f}, 30.0f, "origin on the key space's centre"},
      {0.05, {-17.3f, -8.2f, 1.9f}, 15.0f, "fine voxels"},
      {0.35, {101.7f, -250.3f, 3.3f}, 60.0f, "coarse voxels far from the key centre"},
  };
  std::uint32_t seed = 21;
  for (const Case& c : cases) {
    const test::WorldScan scan = degenerateRays(seed++, c.origin, c.res, c.reach, 4000);
    for (double range : {inf, 20.0, 7.5}) {
      SCOPED_TRACE(testing::Message() << c.what << ", max range " << range);
      const Cast portable = castWith(detail::RayPath::Portable, 8, scan, c.res, range);
      for (int lanes : {2, 4, 8}) {
        const Cast simd = castWith(detail::RayPath::Simd, lanes, scan, c.res, range);
        EXPECT_TRUE(sameCast(portable, simd)) << lanes << " lanes";
      }
      EXPECT_TRUE(portable.dense);
      EXPECT_EQ(portable.counts.non_finite, 1u);
      if (range < c.reach / 2) {
        EXPECT_GT(portable.counts.cut, 1000u);
      }
      EXPECT_GT(freeBits(portable), 20000u);  // a real walk
    }
  }
}

// A box too large for the scan's bit box: the per-block walk (walkAll) on both paths. Voxels
// of 1/64 m and the origin on a voxel corner: crossings tie exactly on the diagonals.
TEST(RayKernel, PortableWalkMarksTheSameVoxelsAsTheSimdWalkBlockByBlock) {
  const double res = 1.0 / 64;
  const test::WorldScan scan = degenerateRays(7, {-1.0f, 0.5f, -0.25f}, res, 40.0f, 150);
  for (double range : {std::numeric_limits<double>::infinity(), 20.0}) {
    SCOPED_TRACE(testing::Message() << "max range " << range);
    const Cast portable = castWith(detail::RayPath::Portable, 8, scan, res, range);
    const Cast simd = castWith(detail::RayPath::Simd, 8, scan, res, range);
    EXPECT_FALSE(portable.dense);
    EXPECT_TRUE(sameCast(portable, simd));
    EXPECT_GT(freeBits(portable), 100000u);
  }
}

using KnownVoxels = std::vector<std::pair<VoxelKey, std::uint32_t>>;

// The map's voxels in its order, each log-odds as its bits.
KnownVoxels knownVoxels(const LogOddsMap& map) {
  KnownVoxels all;
  map.forEachKnown([&](const VoxelKey& k, float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    all.emplace_back(k, bits);
  });
  return all;
}

TEST(RayKernel, PortableWalkBuildsTheSameLogOddsMapAsTheSimdWalk) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<test::WorldScan> scans;
  for (std::size_t frame : {0u, 1u, 2u}) scans.push_back(test::kittiWorldScan(frame));
  for (const auto& [res, range] :
       {std::pair<double, double>{0.2, 50.0}, {0.1, 30.0}, {0.35, inf}}) {
    SCOPED_TRACE(testing::Message() << "res " << res << " range " << range);
    LogOddsParams p;
    p.resolution = res;
    p.max_range = range;
    LogOddsMap simd(p), portable(p);
    for (const test::WorldScan& scan : scans) {
      const ScanInsertReport a = simd.insertScan(scan.points, scan.origin);
      ScanInsertReport b;
      {
        const detail::ScopedRayPath forced(detail::RayPath::Portable);
        b = portable.insertScan(scan.points, scan.origin);
      }
      EXPECT_EQ(a.beams, b.beams);
      EXPECT_EQ(a.beams_cut, b.beams_cut);
      EXPECT_EQ(a.hit_voxels, b.hit_voxels);
      EXPECT_EQ(a.miss_voxels, b.miss_voxels);
    }
    const KnownVoxels va = knownVoxels(simd), vb = knownVoxels(portable);
    ASSERT_EQ(va.size(), vb.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < va.size(); ++i) {
      differ += va[i].first != vb[i].first || va[i].second != vb[i].second ? 1 : 0;
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(va.size(), 100000u);
    EXPECT_GT(simd.occupiedVoxels(), 10000u);
  }
}

}  // namespace
}  // namespace metricmap
