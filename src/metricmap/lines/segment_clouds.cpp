#include "metricmap/lines/segment_clouds.h"

#include <chrono>

namespace metricmap {

SegmentedClouds segmentClouds(SplitAndMerge<pcl::PointXYZ>& segmenter,
                              const std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr>& clouds) {
  SegmentedClouds out;
  out.segments.resize(clouds.size());
  std::vector<pcl::PointIndices> members;
  for (std::size_t k = 0; k < clouds.size(); ++k) {
    segmenter.setInputCloud(clouds[k]);
    const auto t0 = std::chrono::steady_clock::now();
    segmenter.segment(out.segments[k], members);
    out.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return out;
}

}  // namespace metricmap
