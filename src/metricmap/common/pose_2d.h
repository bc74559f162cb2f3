#pragma once
/// \file pose_2d.h
/// \brief A planar pose (SE(2)): the one type logs, pose graphs and the 2D SLAM share.

namespace metricmap {

/// \brief A pose in SE(2): position (x, y) in metres and heading theta in radians.
struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
};

}  // namespace metricmap
