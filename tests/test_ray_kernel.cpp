// The four-lane AVX2 walk marks the same voxels as the two-beam SSE2 walk, bit for bit, on real
// KITTI scans at several resolutions and max ranges (where the CPU has AVX2; elsewhere both
// runs take the SSE2 walk and the test still checks the plumbing).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <utility>

#include "metricmap/occupancy/ray_kernel.h"
#include "occupancy_scans.h"

namespace metricmap {
namespace {

using Words = std::pair<std::vector<std::uint64_t>, std::vector<std::uint64_t>>;

std::map<std::uint64_t, Words> cast(const test::WorldScan& scan, double res, double max_range,
                                    bool simd, detail::RayCastCounts& counts) {
  detail::RayCastInput in;
  in.xyz = &scan.points[0].x;
  in.stride_bytes = sizeof(pcl::PointXYZ);
  in.count = scan.points.size();
  for (int i = 0; i < 3; ++i) in.origin[i] = scan.origin[i];
  in.resolution = res;
  in.max_range = max_range;
  in.simd = simd;
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

TEST(RayKernel, FourLaneWalkMarksTheSameVoxelsAsTheTwoBeamWalk) {
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
      detail::RayCastCounts a, b;
      const auto simd = cast(scan, res, range, true, a);
      const auto plain = cast(scan, res, range, false, b);
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

// Beams through voxel corners and edges: the origin at a voxel's centre, ends at whole-voxel
// offsets with two or three equal components, so the crossing parameters tie at every corner.
TEST(RayKernel, FourLaneWalkBreaksTiesAsTheTwoBeamWalk) {
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
  detail::RayCastCounts a, b;
  const auto simd = cast(scan, res, 100.0, true, a);
  const auto plain = cast(scan, res, 100.0, false, b);
  ASSERT_EQ(simd.size(), plain.size());
  std::size_t differ = 0;
  for (const auto& [key, words] : plain) {
    const auto it = simd.find(key);
    ASSERT_NE(it, simd.end());
    differ += it->second != words ? 1 : 0;
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(a.beams, 500u);
}

}  // namespace
}  // namespace metricmap
