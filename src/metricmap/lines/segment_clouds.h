#pragma once
/// \file segment_clouds.h
/// \brief One Split & Merge run over several scans, timed.

#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/lines/line_segment.h"
#include "metricmap/lines/split_and_merge.h"

namespace metricmap {

/// \brief The segments of each scan, in the scans' order, and the seconds segmentation took.
struct SegmentedClouds {
  std::vector<std::vector<LineSegment>> segments;
  double seconds = 0.0;  ///< time in SplitAndMerge::segment only
};

/// \brief Segment every cloud of `clouds` with `segmenter` (its parameters and step callback
/// as set). \throws what SplitAndMerge::segment throws
SegmentedClouds segmentClouds(SplitAndMerge<pcl::PointXYZ>& segmenter,
                              const std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr>& clouds);

}  // namespace metricmap
