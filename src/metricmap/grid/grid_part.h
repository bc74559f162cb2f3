#pragma once
/// \file grid_part.h
/// \brief One process's part of a grid built by several (each bins its share of the input,
/// GridAccumulator merges the parts by cell index): the cells the one-process build of the
/// whole input gives, for either origin.

#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/grid/grid_types.h"
#include "metricmap/grid/occupancy_grid.h"

namespace metricmap {

/// \brief Per-axis minimum of the cloud's finite points, as the grid kernel takes it (+inf on
/// every axis when no point is finite).
std::vector<double> finiteMinimum(const pcl::PointCloud<pcl::PointXYZ>& cloud);

/// \brief The part of `cloud` built with `grid` (its cell size and threads as set).
///
/// Without `job_min`: a GridOrigin::WorldAligned build. With it: a GridOrigin::CloudMinimum
/// build whose indices are those of the one-process build of the whole input: the cells start
/// at `*job_min`, the minimum over every process's points, not at the share's own minimum. The
/// kernel takes the minimum of its input, so a share whose minimum is above the job's bins its
/// points with one more point at the job's minimum (the same kernel, the same snapping to cell
/// boundaries), then takes that point out of its cell: the first one, whose index is the
/// smallest on every axis. The layout's origin is then set to 0 for GridAccumulator::add, which
/// merges cells by index. `cloud` is left as it was given.
GridResult gridPart(OccupancyGrid<pcl::PointXYZ>& grid,
                    const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
                    const std::vector<double>* job_min);

}  // namespace metricmap
