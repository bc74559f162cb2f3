#pragma once
/// \file scene_types.h
/// \brief What a 3D view shows, without VTK: boxes with counts, 2D segments, view options.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "metricmap/common/segment_2d.h"

namespace metricmap::viz {

/// \brief An axis-aligned box with the number of points it holds.
struct CountedBox {
  Eigen::Vector3d min, max;
  double count = 0;
};

struct SceneOptions {
  std::string title;
  std::string color_by = "height";  ///< height | rgb | count
  int up_axis = 2;                  ///< 0 x, 1 y, 2 z
  std::string camera = "iso";       ///< top | side | iso
};

/// \brief A 2D segment to draw at z = 0 (from `metricmap lines --format json`).
using DrawnSegment = Segment2D;

/// \brief Voxels of an occupancy map to draw as cubes of edge `size` (centres in the world).
struct VoxelLayer {
  std::vector<Eigen::Vector3d> centers;
  double size = 0.0;
};

}  // namespace metricmap::viz
