#include "metricmap/grid/grid_part.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace metricmap {

std::vector<double> finiteMinimum(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  std::vector<double> lo(3, std::numeric_limits<double>::infinity());
  for (const pcl::PointXYZ& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    lo[0] = std::min(lo[0], static_cast<double>(p.x));
    lo[1] = std::min(lo[1], static_cast<double>(p.y));
    lo[2] = std::min(lo[2], static_cast<double>(p.z));
  }
  return lo;
}

GridResult gridPart(OccupancyGrid<pcl::PointXYZ>& grid,
                    const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
                    const std::vector<double>* job_min) {
  if (job_min == nullptr) {
    grid.setOrigin(GridOrigin::WorldAligned);
    grid.setInputCloud(cloud);
    grid.compute();
    return {grid.getLayout(), grid.getCells(), grid.getStatistics()};
  }
  const std::vector<double>& lo = *job_min;
  const std::vector<double> mine = finiteMinimum(*cloud);
  const bool extra = std::isfinite(mine[0]) && mine != lo;
  if (extra) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(lo[0]), static_cast<float>(lo[1]),
                                   static_cast<float>(lo[2])));
    cloud->width = static_cast<std::uint32_t>(cloud->size());
    cloud->height = 1;
  }
  grid.setOrigin(GridOrigin::CloudMinimum);
  grid.setInputCloud(cloud);
  grid.compute();
  GridResult part{grid.getLayout(), grid.getCells(), grid.getStatistics()};
  if (extra) {
    cloud->points.pop_back();
    cloud->width = static_cast<std::uint32_t>(cloud->size());
    GridCell& first = part.cells.front();
    if (first.count == 1) {
      part.cells.erase(part.cells.begin());
    } else {
      const double n = static_cast<double>(first.count);
      const Eigen::Vector3d m(lo[0], lo[1], lo[2]);
      first.mean = (first.mean * n - m) / (n - 1.0);
      --first.count;
    }
  }
  part.layout.origin = Eigen::Vector3d::Zero();
  return part;
}

}  // namespace metricmap
