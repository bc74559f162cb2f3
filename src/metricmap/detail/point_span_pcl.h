#pragma once
/// \file point_span_pcl.h
/// \brief Build a PointSpan from a pcl::PointCloud and optional indices.

#include <pcl/point_cloud.h>
#include <pcl/types.h>

#include "metricmap/detail/point_span.h"

namespace metricmap {

template <typename PointT>
PointSpan makePointSpan(const pcl::PointCloud<PointT>& cloud, const pcl::Indices* indices) {
  static_assert(sizeof(pcl::index_t) == sizeof(int), "metricmap expects 32-bit pcl::index_t");
  PointSpan span;
  span.base = cloud.empty() ? nullptr : &cloud.points[0].x;
  span.stride = sizeof(PointT);
  if (indices != nullptr) {
    span.indices = indices->data();
    span.size = indices->size();
  } else {
    span.size = cloud.size();
  }
  return span;
}

}  // namespace metricmap
