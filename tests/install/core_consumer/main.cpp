// Uses only metricmap::core: a cloud made in memory, the grid against a plain count, the octree
// and Split & Merge.
#include <cmath>
#include <iostream>
#include <map>
#include <tuple>

#include <metricmap/grid/occupancy_grid.h>
#include <metricmap/lines/split_and_merge.h>
#include <metricmap/octree/adaptive_octree.h>

int main() {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int i = 0; i < 20000; ++i) {  // a deterministic spiral over a few metres
    const double t = 0.001 * i;
    cloud->push_back(pcl::PointXYZ(static_cast<float>(3.0 * std::cos(7.0 * t) * t),
                                   static_cast<float>(3.0 * std::sin(7.0 * t) * t),
                                   static_cast<float>(0.1 * t)));
  }
  const float cell = 0.25f;
  metricmap::OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(cell);
  grid.setOrigin(metricmap::GridOrigin::WorldAligned);
  grid.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ> cells;
  grid.filter(cells);
  std::map<std::tuple<long, long, long>, int> reference;  // floor(p / cell), as VoxelGrid
  for (const auto& p : *cloud)
    ++reference[{static_cast<long>(std::floor(p.x * (1.0f / cell))),
                 static_cast<long>(std::floor(p.y * (1.0f / cell))),
                 static_cast<long>(std::floor(p.z * (1.0f / cell)))}];

  metricmap::AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(50);
  octree.setMinCellSize(0.1f);
  octree.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ> leaves;
  octree.filter(leaves);

  auto scan = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int i = 0; i <= 50; ++i) scan->push_back(pcl::PointXYZ(0.02f * i, 1.0f, 0.0f));
  for (int i = 1; i <= 50; ++i) scan->push_back(pcl::PointXYZ(1.0f, 1.0f + 0.02f * i, 0.0f));
  metricmap::SplitAndMerge<pcl::PointXYZ> sam;
  sam.setInputCloud(scan);
  std::vector<metricmap::LineSegment> segments;
  std::vector<pcl::PointIndices> members;
  sam.segment(segments, members);

  std::cout << "core: " << cells.size() << " cells (reference " << reference.size() << "), "
            << leaves.size() << " leaves, " << segments.size() << " segments\n";
  const bool ok = cells.size() == reference.size() && !leaves.empty() &&
                  leaves.size() == octree.getStatistics().occupied_leaves && segments.size() == 2;
  return ok ? 0 : 1;
}
