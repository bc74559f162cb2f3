#pragma once
/// \file metricmap.h
/// \brief Umbrella header: every public class of metricmap.

#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/array_writers.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/depth_image.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/lines/line_segment.h"
#include "metricmap/lines/split_and_merge.h"
#include "metricmap/mapping/floor_fit.h"
#include "metricmap/mapping/height_map.h"
#include "metricmap/mapping/occupancy_map_2d.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "metricmap/occupancy/octomap_io.h"
#include "metricmap/octree/adaptive_octree.h"
#include "metricmap/version.h"
