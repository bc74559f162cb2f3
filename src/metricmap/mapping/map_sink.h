#pragma once
/// \file map_sink.h
/// \brief A map sink: a pure consumer of (scan, pose) that grows one map. The mapping pipeline
/// (sequence/scan_mapper) drives a list of sinks; a sink never reads files nor estimates poses,
/// and is rebuilt from a new trajectory by inserting the scans again.

#include <cstdint>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

namespace metricmap {

/// \brief One scan as every sink sees it.
struct SinkScan {
  /// The scan as given, in the sensor frame (every point, no range band).
  const pcl::PointCloud<pcl::PointXYZ>& in_sensor;
  /// The points within the range band, in the world.
  const pcl::PointCloud<pcl::PointXYZ>& world;
  /// `world` averaged in the pipeline's voxel cells (the same cloud when averaging is off).
  const pcl::PointCloud<pcl::PointXYZ>& averaged;
  /// Sensor -> world.
  const Eigen::Isometry3d& pose;
};

/// \brief The interface of every map sink.
class MapSink {
 public:
  virtual ~MapSink() = default;
  /// \brief Adds one scan; returns how many points or beams the map took from it.
  virtual std::uint64_t insert(const SinkScan& scan) = 0;
};

}  // namespace metricmap
