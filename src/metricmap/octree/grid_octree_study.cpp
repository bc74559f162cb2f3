#include "metricmap/octree/grid_octree_study.h"

#include <chrono>

#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/octree/adaptive_octree.h"

namespace metricmap {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

GridOctreeFigures gridOctreeFigures(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                                    float cell_size, float min_cell_size, std::size_t max_points) {
  GridOctreeFigures r;
  auto t = std::chrono::steady_clock::now();
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(cell_size);
  grid.setInputCloud(cloud);
  grid.compute();
  r.grid = grid.getStatistics();
  r.grid_s = secondsSince(t);

  t = std::chrono::steady_clock::now();
  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(max_points);
  octree.setMinCellSize(min_cell_size);
  octree.setInputCloud(cloud);
  octree.compute();
  r.octree = octree.getStatistics();
  r.octree_s = secondsSince(t);
  return r;
}

}  // namespace metricmap
