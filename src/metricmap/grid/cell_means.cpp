#include "metricmap/grid/cell_means.h"

namespace metricmap {

pcl::PointCloud<pcl::PointXYZ> cellMeans(const std::vector<GridCell>& cells) {
  pcl::PointCloud<pcl::PointXYZ> means;
  fillCellMeans<pcl::PointXYZ>(cells, nullptr, means);
  return means;
}

}  // namespace metricmap
