#pragma once
/// \file metricmap.h
/// \brief Umbrella header: every public class of metricmap.

#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/lines/line_segment.h"
#include "metricmap/lines/split_and_merge.h"
#include "metricmap/octree/adaptive_octree.h"
#include "metricmap/version.h"
