#pragma once
/// \file slam_2d_overlay.h
/// \brief What a picture of a SLAM map draws over it: the path and the loop closures.

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace metricmap {

class Slam2D;

struct Slam2DOverlay {
  std::vector<Eigen::Vector2d> path;  ///< every node's position, in node order
  /// Each kept loop closure from the centre of the submap matched to its node. (The edge's
  /// other end, the submap's first node, would draw lines across the whole map.)
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> links;
};

/// \brief The path and loop closures of `slam` (global frame, metres).
Slam2DOverlay slam2DOverlay(const Slam2D& slam);

}  // namespace metricmap
