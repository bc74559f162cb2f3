#pragma once
/// \file segment_2d.h
/// \brief A 2D line segment between two points (metres), as line maps store and draw them.

#include <Eigen/Core>

namespace metricmap {

/// \brief A segment from `start` to `end` in the plane.
struct Segment2D {
  Eigen::Vector2d start, end;
};

}  // namespace metricmap
