#pragma once
/// \file kitti_outputs.h
/// \brief The files `metricmap kitti` writes: their checks before any work (distinct from each
/// other and from the inputs, the extension each format needs) and their writing, staged.

#include <cstddef>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "kitti_options.h"
#include "metricmap/io/output_set.h"

namespace metricmap {
struct MapImage;
}

namespace metricmap::cli {

/// \brief Usage errors (exit 2): an output naming an input or another output, an output whose
/// name does not end as its format. \throws UsageError
void checkKittiOutputs(const KittiOptions& o, const std::vector<std::size_t>& frames);

/// \brief Stage and write --out-poses, --out-cloud, --out-octomap, --out-trinary and --out-map
/// (`image`: the run's 2D map, `global`: its global cloud).
void writeKittiOutputs(const KittiOptions& o, const KittiMappingRun& run, const MapImage& image,
                       const pcl::PointCloud<pcl::PointXYZ>& global, OutputSet& outputs);

}  // namespace metricmap::cli
