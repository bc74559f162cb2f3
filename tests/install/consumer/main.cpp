#include <iostream>

#include <metricmap/metricmap.h>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  metricmap::loadCloud(argv[1], *cloud);

  metricmap::OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(1.0f);
  grid.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ> cells;
  grid.filter(cells);

  metricmap::AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(100);
  octree.setMinCellSize(1.0f);
  octree.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ> leaves;
  octree.filter(leaves);

  // Split & Merge on an L of points: two walls.
  auto scan = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int i = 0; i <= 50; ++i) scan->push_back(pcl::PointXYZ(0.02f * i, 1.0f, 0.0f));
  for (int i = 1; i <= 50; ++i) scan->push_back(pcl::PointXYZ(1.0f, 1.0f + 0.02f * i, 0.0f));
  metricmap::SplitAndMerge<pcl::PointXYZ> sam;
  sam.setInputCloud(scan);
  std::vector<metricmap::LineSegment> segments;
  std::vector<pcl::PointIndices> members;
  sam.segment(segments, members);

  std::cout << segments.size() << " segments; metricmap " << METRICMAP_VERSION << ": "
            << cloud->size() << " points, " << grid.getStatistics().occupied_cells
            << " occupied cells, " << octree.getStatistics().occupied_leaves
            << " occupied leaves\n";
  const bool ok = cells.size() == grid.getStatistics().occupied_cells &&
                  leaves.size() == octree.getStatistics().occupied_leaves && segments.size() == 2;
  return ok ? 0 : 1;
}
