#include <pcl/point_types.h>

#include "metricmap/lines/impl/split_and_merge.hpp"

template class metricmap::SplitAndMerge<pcl::PointXYZ>;
template class metricmap::SplitAndMerge<pcl::PointXYZI>;
template class metricmap::SplitAndMerge<pcl::PointXYZRGB>;
