#include "metricmap/viz/scene_content.h"

#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/octree/adaptive_octree.h"

namespace metricmap::viz {

OctreeBoxes octreeBoxes(const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& cloud,
                        std::size_t max_points, float min_cell_size, bool show_empty) {
  AdaptiveOctree<pcl::PointXYZRGB> octree;
  octree.setMaxPointsPerLeaf(max_points);
  octree.setMinCellSize(min_cell_size);
  octree.setInputCloud(cloud);
  octree.compute();
  OctreeBoxes out;
  out.point_counts.assign(cloud->size(), 0.0);
  const auto& nodes = octree.getNodes();
  const std::vector<OctreeBox> bounds = octree.getResult().allBounds();
  for (std::size_t id = 0; id < nodes.size(); ++id) {
    const OctreeNode& n = nodes[id];
    if (!n.isLeaf() || (n.count == 0 && !show_empty)) continue;
    out.boxes.push_back({bounds[id].min, bounds[id].max, static_cast<double>(n.count)});
    for (int i : octree.getPointIndices(id))
      out.point_counts[static_cast<std::size_t>(i)] = n.count;
  }
  out.statistics = octree.getStatistics();
  return out;
}

GridBoxes gridBoxes(const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& cloud, float cell_size) {
  OccupancyGrid<pcl::PointXYZRGB> grid;
  grid.setCellSize(cell_size);
  grid.setInputCloud(cloud);
  grid.compute();
  GridBoxes out;
  for (const GridCell& c : grid.getCells()) {
    const Eigen::Vector3d lo = grid.getCellMin(c.index);
    out.boxes.push_back(
        {lo, lo + Eigen::Vector3d::Constant(cell_size), static_cast<double>(c.count)});
  }
  out.statistics = grid.getStatistics();
  return out;
}

}  // namespace metricmap::viz
