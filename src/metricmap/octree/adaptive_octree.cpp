#include <pcl/point_types.h>

#include "metricmap/octree/impl/adaptive_octree.hpp"

template class metricmap::AdaptiveOctree<pcl::PointXYZ>;
template class metricmap::AdaptiveOctree<pcl::PointXYZI>;
template class metricmap::AdaptiveOctree<pcl::PointXYZRGB>;
