#pragma once
/// \file posegraph.h
/// \brief The Python PoseGraph object (a 2D or a 3D graph), shared with the SLAM binding.

#include "arrays.h"
#include "metricmap/posegraph/pose_graph.h"
#include "object_lock.h"

namespace metricmap::python {

struct PyPoseGraph {
  int dimension = 2;
  PoseGraph2D graph2d;
  PoseGraph3D graph3d;
  bool chained_guess = false;
  mutable ObjectMutex mutex;  ///< serialises the object's calls
};

}  // namespace metricmap::python
