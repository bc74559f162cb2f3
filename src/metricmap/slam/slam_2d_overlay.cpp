#include "metricmap/slam/slam_2d_overlay.h"

#include "metricmap/slam/slam_2d.h"

namespace metricmap {

Slam2DOverlay slam2DOverlay(const Slam2D& slam) {
  Slam2DOverlay overlay;
  for (const auto& v : slam.graph().vertices()) overlay.path.emplace_back(v.pose.x, v.pose.y);
  const std::vector<Eigen::Vector2d> centres = slam.submapCentres();
  for (const LoopClosure2D& l : slam.loops()) {
    const Pose2D b = slam.graph().vertex(l.node).pose;
    overlay.links.emplace_back(centres[l.submap], Eigen::Vector2d(b.x, b.y));
  }
  return overlay;
}

}  // namespace metricmap
