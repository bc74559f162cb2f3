// A cubic-root AdaptiveOctree with max_points 0 is a full octree down to min_cell_size: its
// occupied leaves must be pcl::octree's occupied voxels at that resolution, point for point.
#include <map>
#include <tuple>

#include <pcl/common/common.h>
#include <pcl/octree/octree_pointcloud_pointvector.h>

#include <gtest/gtest.h>

#include "metricmap/io/cloud_reader.h"
#include "metricmap/octree/adaptive_octree.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Key = std::tuple<long, long, long>;

class OctreeVsPcl : public ::testing::TestWithParam<std::pair<const char*, double>> {};

TEST_P(OctreeVsPcl, SameOccupiedLeaves) {
  auto cloud = std::make_shared<Cloud>();
  loadCloud(dataPath(GetParam().first), *cloud);
  const double res = GetParam().second;  // a power of two, so every boundary is exact

  // A cube of side res * 2^k that starts on the res lattice and holds the cloud strictly
  // inside (pcl::octree grows the tree for points on its max faces).
  Eigen::Vector4f lo4, hi4;
  pcl::getMinMax3D(*cloud, lo4, hi4);
  Eigen::Vector3d lo = (lo4.head<3>().cast<double>() / res).array().floor() * res;
  const double extent = (hi4.head<3>().cast<double>() - lo).maxCoeff();
  int k = 0;
  while (std::ldexp(res, k) <= extent) ++k;
  const double side = std::ldexp(res, k);

  pcl::octree::OctreePointCloudPointVector<pcl::PointXYZ> pcl_octree(res);
  pcl_octree.defineBoundingBox(lo.x(), lo.y(), lo.z(), lo.x() + side, lo.y() + side, lo.z() + side);
  pcl_octree.setInputCloud(cloud);
  pcl_octree.addPointsFromInputCloud();
  ASSERT_EQ(pcl_octree.getTreeDepth(), static_cast<unsigned>(k));
  std::map<Key, std::size_t> expected;
  for (auto it = pcl_octree.leaf_depth_begin(); it != pcl_octree.leaf_depth_end(); ++it) {
    const pcl::octree::OctreeKey& key = it.getCurrentOctreeKey();
    expected[Key{key.x, key.y, key.z}] = it.getLeafContainer().getSize();
  }

  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setRootBox(lo, lo.array() + side);
  octree.setMaxPointsPerLeaf(0);
  octree.setMinCellSize(static_cast<float>(res));
  octree.setInputCloud(cloud);
  octree.compute();
  std::map<Key, std::size_t> actual;
  for (std::size_t id : octree.getOccupiedLeaves()) {
    const OctreeNode& n = octree.getNodes()[id];
    ASSERT_EQ(n.depth, static_cast<unsigned>(k));
    const Eigen::Vector3d key = ((octree.getNodeBounds(id).min - lo) / res).array().round();
    actual[Key{static_cast<long>(key.x()), static_cast<long>(key.y()),
               static_cast<long>(key.z())}] = n.count;
  }
  EXPECT_EQ(octree.getStatistics().occupied_leaves, pcl_octree.getLeafCount());
  EXPECT_EQ(actual, expected);
}

INSTANTIATE_TEST_SUITE_P(
    RealClouds, OctreeVsPcl,
    ::testing::Values(std::make_pair("pcl_test_pcd/bunny.pcd", 1.0 / 256),
                      std::make_pair("pcl_test_pcd/cturtle.pcd", 1.0 / 32),
                      std::make_pair("pcl_test_pcd/car6.pcd", 1.0 / 16),
                      std::make_pair("ua_mapas_metricos_pcd/museo000.pcd", 0.25),
                      std::make_pair("kitti_odometry_00/sequences/00/velodyne/000000.bin", 0.5)),
    [](const auto& info) {
      std::string name = info.param.first;
      name = name.substr(name.find_last_of('/') + 1);
      return name.substr(0, name.find('.')) + "_" + std::to_string(info.index);
    });

}  // namespace
}  // namespace metricmap
