#include <pcl/point_types.h>

#include "metricmap/grid/impl/occupancy_grid.hpp"

template class metricmap::OccupancyGrid<pcl::PointXYZ>;
template class metricmap::OccupancyGrid<pcl::PointXYZI>;
template class metricmap::OccupancyGrid<pcl::PointXYZRGB>;
