// Instantiated for every PCL point type with x, y, z (PCL_XYZ_POINT_TYPES): the kernels read
// x, y, z at the start of each point (checked below), whatever else the type carries.
#include <cstddef>

#include <pcl/point_types.h>
#include <pcl/impl/instantiate.hpp>

#include "metricmap/octree/adaptive_octree.h"
#include "metricmap/octree/impl/adaptive_octree.hpp"

#define PCL_INSTANTIATE_AdaptiveOctree(T)                                          \
  static_assert(offsetof(T, x) == 0 && offsetof(T, y) == 4 && offsetof(T, z) == 8, \
                "x, y, z must lead the point");                                    \
  template class metricmap::AdaptiveOctree<T>;
PCL_INSTANTIATE(AdaptiveOctree, PCL_XYZ_POINT_TYPES)
