#include "metricmap/viz/view_content.h"

#include <cmath>
#include <sstream>

#include "metricmap/exceptions.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "metricmap/viz/scene_content.h"

namespace metricmap::viz {

void appendScanPoints(const pcl::PointCloud<pcl::PointXYZ>& scan,
                      pcl::PointCloud<pcl::PointXYZRGB>& out) {
  for (const auto& p : scan) {
    if (!std::isfinite(p.x)) continue;
    pcl::PointXYZRGB q;
    q.x = p.x;
    q.y = p.y;
    q.z = 0.0f;
    q.r = q.g = q.b = 200;
    out.push_back(q);
  }
}

void addMapVoxels(const LogOddsMap& map, const std::string& name, bool with_free,
                  VoxelLayer& occupied, VoxelLayer& free) {
  if (occupied.size > 0 && occupied.size != map.resolution()) {
    throw InputError(name + ": resolution " + std::to_string(map.resolution()) +
                     " differs from the other map's " + std::to_string(occupied.size));
  }
  occupied.size = free.size = map.resolution();
  for (const auto& c : voxelCenters(map, true)) occupied.centers.push_back(c);
  if (with_free)
    for (const auto& c : voxelCenters(map, false)) free.centers.push_back(c);
}

StructureBoxes structureBoxes(const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& cloud,
                              const StructureSettings& s) {
  StructureBoxes out;
  std::ostringstream title;
  if (s.octree) {
    OctreeBoxes ob = octreeBoxes(cloud, s.max_points, s.min_cell_size, s.show_empty);
    out.boxes = std::move(ob.boxes);
    out.point_counts = std::move(ob.point_counts);
    title << " | octree max_points " << s.max_points << ", min_cell " << s.min_cell_size << ": "
          << ob.statistics.occupied_leaves << " occupied / " << ob.statistics.leaf_nodes
          << " leaves";
  }
  if (s.grid) {
    const GridBoxes gb = gridBoxes(cloud, s.cell_size);
    out.boxes.insert(out.boxes.end(), gb.boxes.begin(), gb.boxes.end());
    title << " | grid cell " << s.cell_size << ": " << gb.statistics.occupied_cells
          << " occupied cells";
  }
  out.title = title.str();
  return out;
}

}  // namespace metricmap::viz
