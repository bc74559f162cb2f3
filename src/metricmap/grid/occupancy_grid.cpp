// Instantiated for every PCL point type with x, y, z (PCL_XYZ_POINT_TYPES): the kernels read
// x, y, z at the start of each point (checked below), whatever else the type carries.
#include <cstddef>

#include <pcl/point_types.h>
#include <pcl/impl/instantiate.hpp>

#include "metricmap/grid/impl/occupancy_grid.hpp"
#include "metricmap/grid/occupancy_grid.h"

#define PCL_INSTANTIATE_OccupancyGrid(T)                                           \
  static_assert(offsetof(T, x) == 0 && offsetof(T, y) == 4 && offsetof(T, z) == 8, \
                "x, y, z must lead the point");                                    \
  template class metricmap::OccupancyGrid<T>;
PCL_INSTANTIATE(OccupancyGrid, PCL_XYZ_POINT_TYPES)
