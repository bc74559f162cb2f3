// OccupancyGrid(WorldAligned) against pcl::VoxelGrid on real clouds: same cells, same means.
#include <pcl/filters/voxel_grid.h>

#include <gtest/gtest.h>

#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

struct Case {
  const char* file;
  float leaf;
};

class VoxelGridOracle : public ::testing::TestWithParam<Case> {};

TEST_P(VoxelGridOracle, SameCellsAndMeans) {
  auto cloud = std::make_shared<Cloud>();
  loadCloud(dataPath(GetParam().file), *cloud);
  const float leaf = GetParam().leaf;

  pcl::VoxelGrid<pcl::PointXYZ> voxel;
  voxel.setInputCloud(cloud);
  voxel.setLeafSize(leaf, leaf, leaf);
  voxel.setSaveLeafLayout(true);
  Cloud expected;
  voxel.filter(expected);
  ASSERT_LT(expected.size(), cloud->size()) << "VoxelGrid did not reduce the cloud";
  // VoxelGrid's partition: which output point each input point went to.
  std::vector<std::uint64_t> expected_counts(expected.size(), 0);
  for (const pcl::PointXYZ& p : *cloud) {
    const int k = voxel.getCentroidIndex(p);
    ASSERT_GE(k, 0);
    ++expected_counts[static_cast<std::size_t>(k)];
  }

  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setOrigin(GridOrigin::WorldAligned);
  grid.setCellSize(leaf);
  grid.setInputCloud(cloud);
  Cloud actual;
  grid.filter(actual);

  ASSERT_EQ(actual.size(), expected.size());
  const auto& cells = grid.getCells();
  for (std::size_t i = 0; i < actual.size(); ++i) {
    // Same order (both sort by linear cell index): the same cell at the same position, holding
    // the same number of points; its first point is one VoxelGrid put in that cell too.
    EXPECT_EQ(voxel.getCentroidIndex((*cloud)[cells[i].first_point]), static_cast<int>(i));
    EXPECT_EQ(cells[i].count, expected_counts[i]) << "cell " << i;
    const float tol = 1e-5f * std::max(1.0f, expected[i].getVector3fMap().cwiseAbs().maxCoeff());
    EXPECT_NEAR(actual[i].x, expected[i].x, tol) << "cell " << i;
    EXPECT_NEAR(actual[i].y, expected[i].y, tol) << "cell " << i;
    EXPECT_NEAR(actual[i].z, expected[i].z, tol) << "cell " << i;
  }
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  std::string name = info.param.file;
  name = name.substr(name.find_last_of('/') + 1);
  name = name.substr(0, name.find('.'));
  return name + "_" + std::to_string(static_cast<int>(info.param.leaf * 1000)) + "mm";
}

INSTANTIATE_TEST_SUITE_P(
    RealClouds, VoxelGridOracle,
    ::testing::Values(Case{"pcl_test_pcd/bunny.pcd", 0.01f}, Case{"pcl_test_pcd/milk.pcd", 0.005f},
                      Case{"pcl_test_pcd/car6.pcd", 0.1f}, Case{"pcl_test_pcd/cturtle.pcd", 0.05f},
                      Case{"pcl_test_pcd/lamppost.pcd", 0.1f},
                      Case{"pcl_test_pcd/table_scene_mug_stereo_textured.pcd", 0.01f},
                      Case{"ua_mapas_metricos_pcd/ciencias000.pcd", 0.5f},
                      Case{"ua_mapas_metricos_pcd/museo000.pcd", 0.1f},
                      Case{"kitti_odometry_00/sequences/00/velodyne/000000.bin", 0.1f}),
    caseName);

}  // namespace
}  // namespace metricmap
