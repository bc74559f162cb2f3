#pragma once
/// \file pcl_peer.h
/// \brief The same job done by pcl::octree, for `compare --pcl-octree`.

#include <cstddef>
#include <cstdint>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace metricmap::cli {

struct PclOctreeFigures {
  std::uint64_t leaves = 0;
  unsigned depth = 0;
  double seconds = 0.0;
};

/// \brief OctreePointCloudPointVector at `resolution` with enableDynamicDepth(max_points).
PclOctreeFigures runPclOctree(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                              double resolution, std::size_t max_points);

}  // namespace metricmap::cli
