#pragma once
/// \file metricmap.h
/// \brief Umbrella header: every public class of metricmap.

#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/octree/adaptive_octree.h"
#include "metricmap/version.h"
