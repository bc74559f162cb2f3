#include "concatenated_cloud.h"

#include <memory>

namespace metricmap::cli {

LoadedCloud loadConcatenated(const std::vector<std::string>& files, std::size_t first,
                             std::size_t last) {
  if (first >= last) return {std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(), {}, 0.0};
  LoadedCloud all = loadTimed(files[first]);
  for (std::size_t i = first + 1; i < last; ++i) {
    const LoadedCloud more = loadTimed(files[i]);
    all.seconds += more.seconds;
    *all.cloud += *more.cloud;
  }
  return all;
}

}  // namespace metricmap::cli
