// computeBounds: the vector path (whole clouds) against a plain loop written here, with NaN and
// Inf in every coordinate, signed zeros and several point layouts; the index path too.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/detail/bounds.h"
#include "metricmap/detail/point_span_pcl.h"

namespace metricmap {
namespace {

template <typename PointT>
void checkBounds(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-500.0f, 500.0f);
  std::uniform_int_distribution<int> kind(0, 9);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  pcl::PointCloud<PointT> cloud;
  for (int i = 0; i < 5000; ++i) {
    PointT p;
    p.x = u(rng);
    p.y = u(rng);
    p.z = u(rng);
    const int k = kind(rng);
    if (k == 0) p.x = nan;
    if (k == 1) p.y = -inf;
    if (k == 2) p.z = inf;
    if (k == 3) p.data[3] = nan;  // padding lane: must not matter
    if (k == 4) p.z = -0.0f;
    cloud.push_back(p);
  }
  float lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
  std::size_t finite = 0;
  pcl::Indices all;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    all.push_back(static_cast<int>(i));
    const PointT& p = cloud[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    ++finite;
    const float c[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], c[a]);
      hi[a] = std::max(hi[a], c[a]);
    }
  }
  for (const pcl::Indices* indices :
       {static_cast<const pcl::Indices*>(nullptr), static_cast<const pcl::Indices*>(&all)}) {
    const Bounds b = computeBounds(makePointSpan(cloud, indices));
    EXPECT_EQ(b.finite, finite);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(b.min[a], lo[a]) << "axis " << a << (indices ? " (indices)" : "");
      EXPECT_EQ(b.max[a], hi[a]) << "axis " << a << (indices ? " (indices)" : "");
    }
  }
}

TEST(Bounds, MatchAPlainLoopWithNonFinitePoints) {
  checkBounds<pcl::PointXYZ>(1);
  checkBounds<pcl::PointXYZI>(2);
  checkBounds<pcl::PointXYZRGB>(3);
  checkBounds<pcl::PointNormal>(4);
}

TEST(Bounds, AllNonFiniteLeavesNothingFinite) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back(pcl::PointXYZ(std::nanf(""), 0, 0));
  cloud.push_back(pcl::PointXYZ(0, 0, std::numeric_limits<float>::infinity()));
  EXPECT_EQ(computeBounds(makePointSpan(cloud, nullptr)).finite, 0u);
}

}  // namespace
}  // namespace metricmap
