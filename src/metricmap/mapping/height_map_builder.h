#pragma once
/// \file height_map_builder.h
/// \brief Frames into a height map, each at its camera-to-map pose: a fixed pose, the k-th pose
/// of a trajectory, or the pose of the floor fitted in the frame itself.

#include <cstddef>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include "metricmap/mapping/floor_fit.h"

namespace metricmap {

class HeightMap;

/// \brief Where frame k's camera-to-map pose comes from (the first that applies).
struct HeightMapPoses {
  bool auto_floor = false;       ///< fit the floor of every frame (RANSAC) and stand on it
  double floor_distance = 0.02;  ///< the floor fit's inlier distance (m)
  std::vector<Eigen::Isometry3d> trajectory;  ///< frame k takes trajectory[k] when not empty
  Eigen::Isometry3d fixed = Eigen::Isometry3d::Identity();  ///< else every frame takes this
};

/// \brief The floor fitted in one frame (HeightMapPoses::auto_floor).
struct HeightMapFloor {
  std::size_t frame = 0;
  FloorPlane plane;
};

/// \brief Adds camera-frame clouds to a height map, frame after frame.
/// \note Thread safety: one instance per thread.
class HeightMapBuilder {
 public:
  /// \brief `map` must outlive the builder.
  HeightMapBuilder(HeightMap& map, HeightMapPoses poses);

  /// \brief Add the next frame (frame k is the k-th call) at its pose.
  /// \throws std::runtime_error when auto_floor finds no floor; std::out_of_range past the
  /// trajectory's last pose
  void addFrame(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud);

  /// \brief The floors fitted so far, one per frame (auto_floor only).
  const std::vector<HeightMapFloor>& floors() const { return floors_; }
  /// \brief Seconds spent adding points to the map (not fitting floors).
  double seconds() const { return seconds_; }

 private:
  HeightMap& map_;
  HeightMapPoses poses_;
  std::vector<HeightMapFloor> floors_;
  std::size_t frames_ = 0;
  double seconds_ = 0.0;
};

}  // namespace metricmap
