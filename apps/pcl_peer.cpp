#include "pcl_peer.h"

#include <pcl/octree/octree_pointcloud_pointvector.h>

#include "cli_common.h"

namespace metricmap::cli {

PclOctreeFigures runPclOctree(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                              double resolution, std::size_t max_points) {
  const auto t0 = std::chrono::steady_clock::now();
  pcl::octree::OctreePointCloudPointVector<pcl::PointXYZ> octree(resolution);
  octree.enableDynamicDepth(max_points);
  octree.setInputCloud(cloud);
  octree.addPointsFromInputCloud();
  PclOctreeFigures f;
  f.seconds = secondsSince(t0);
  f.leaves = octree.getLeafCount();
  f.depth = octree.getTreeDepth();
  return f;
}

}  // namespace metricmap::cli
