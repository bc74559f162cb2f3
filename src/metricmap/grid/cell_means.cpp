#include "metricmap/grid/cell_means.h"

#include <cstdint>

namespace metricmap {

pcl::PointCloud<pcl::PointXYZ> cellMeans(const std::vector<GridCell>& cells) {
  pcl::PointCloud<pcl::PointXYZ> means;
  means.resize(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    means[i].x = static_cast<float>(cells[i].mean.x());
    means[i].y = static_cast<float>(cells[i].mean.y());
    means[i].z = static_cast<float>(cells[i].mean.z());
  }
  means.width = static_cast<std::uint32_t>(means.size());
  means.height = 1;
  means.is_dense = true;
  return means;
}

}  // namespace metricmap
