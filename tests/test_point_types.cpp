// The grid and the octree on PCL point types other than PointXYZ (all of PCL_XYZ_POINT_TYPES are
// instantiated): the same cells, nodes and means as the PointXYZ build of the same coordinates.
#include <gtest/gtest.h>

#include <pcl/common/io.h>

#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/octree/adaptive_octree.h"
#include "test_data.h"

namespace metricmap {
namespace {

template <typename PointT>
class PointTypes : public ::testing::Test {};

using Types =
    ::testing::Types<pcl::PointXYZRGBA, pcl::PointXYZL, pcl::PointNormal, pcl::PointXYZRGBNormal,
                     pcl::PointXYZINormal, pcl::PointWithViewpoint, pcl::PointXYZLNormal>;
TYPED_TEST_SUITE(PointTypes, Types);

TYPED_TEST(PointTypes, GridAndOctreeMatchPointXyz) {
  auto xyz = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  loadCloud(studyScan("museo000"), *xyz);
  auto other = std::make_shared<pcl::PointCloud<TypeParam>>();
  pcl::copyPointCloud(*xyz, *other);
  ASSERT_EQ(other->size(), xyz->size());

  OccupancyGrid<pcl::PointXYZ> g1;
  OccupancyGrid<TypeParam> g2;
  g1.setCellSize(0.5f);
  g2.setCellSize(0.5f);
  g1.setInputCloud(xyz);
  g2.setInputCloud(other);
  g1.compute();
  g2.compute();
  ASSERT_GT(g1.getCells().size(), 100u);
  ASSERT_EQ(g1.getCells().size(), g2.getCells().size());
  for (std::size_t i = 0; i < g1.getCells().size(); ++i) {
    const GridCell &a = g1.getCells()[i], &b = g2.getCells()[i];
    ASSERT_EQ(a.index, b.index);
    ASSERT_EQ(a.count, b.count);
    ASSERT_EQ(a.mean, b.mean);
  }

  AdaptiveOctree<pcl::PointXYZ> o1;
  AdaptiveOctree<TypeParam> o2;
  o1.setMaxPointsPerLeaf(20);
  o2.setMaxPointsPerLeaf(20);
  o1.setMinCellSize(0.1f);
  o2.setMinCellSize(0.1f);
  o1.setInputCloud(xyz);
  o2.setInputCloud(other);
  o1.compute();
  o2.compute();
  ASSERT_GT(o1.getNodes().size(), 100u);
  ASSERT_EQ(o1.getNodes().size(), o2.getNodes().size());
  for (std::size_t i = 0; i < o1.getNodes().size(); ++i) {
    const OctreeNode &a = o1.getNodes()[i], &b = o2.getNodes()[i];
    ASSERT_EQ(o1.getNodeBounds(i).min, o2.getNodeBounds(i).min);
    ASSERT_EQ(o1.getNodeBounds(i).max, o2.getNodeBounds(i).max);
    ASSERT_EQ(a.count, b.count);
    ASSERT_EQ(a.mean, b.mean);
    ASSERT_EQ(a.first_child, b.first_child);
  }
}

}  // namespace
}  // namespace metricmap
