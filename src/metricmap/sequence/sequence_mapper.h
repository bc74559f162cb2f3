#pragma once
/// \file sequence_mapper.h
/// \brief Maps of a sequence built from a trajectory: the scans are read again from their
/// source, one at a time, and fused at the given poses (the hit map, the global cloud and the
/// log-odds map of a ScanMapper, as configured). The maps are pure consumers of (scan, pose): a
/// corrected trajectory (a better estimator, loop closure, the user's own poses) rebuilds them
/// with another call, holding one scan and the maps in memory, never the whole sequence.

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/sequence/odometry_run.h"
#include "metricmap/sequence/scan_mapper.h"

namespace metricmap {

/// \brief The map's world for a source: KITTI's camera 0 of the first frame (up -y, maps in the
/// XZ plane), as `metricmap kitti` builds it; otherwise the world of the poses (up +z, XY plane).
struct MapConvention {
  Eigen::Vector3f up = Eigen::Vector3f(0, 0, 1);
  MapPlane plane = MapPlane::XY;
};
MapConvention mapConvention(const SourceInfo& info);

/// \brief Sensor -> map world poses of `frames` from the source's reference (KITTI: P Tr).
/// \throws InputError naming the source when it has no reference
std::vector<Eigen::Isometry3d> referenceSensorPoses(const ScanSource& source,
                                                    const std::vector<std::size_t>& frames);

/// \brief Sensor -> map world poses of an odometry run's frames (KITTI: the camera poses
/// times Tr; otherwise the run's poses).
std::vector<Eigen::Isometry3d> odometrySensorPoses(const OdometryRun& run, const SourceInfo& info);

/// \brief Builds (and rebuilds) the maps of one source. Not thread-safe.
class SequenceMapper {
 public:
  using Observer = std::function<void(const FrameReport&, std::size_t done, std::size_t total)>;

  /// \throws std::invalid_argument for a bad configuration
  SequenceMapper(ScanSource& source, const ScanMapperConfig& config);

  /// \brief Forget the maps and fuse the scans `frames` (empty: every scan) at `poses` (sensor
  /// -> map world, one per frame).
  /// \throws std::invalid_argument when the counts differ or the frames are not increasing
  /// \throws InputError naming a scan that cannot be read
  const ScanMapper& build(const std::vector<Eigen::Isometry3d>& poses,
                          const std::vector<std::size_t>& frames = {},
                          const Observer& observer = {});

  /// \brief The maps of the last build. \throws std::logic_error before the first build
  const ScanMapper& maps() const;

 private:
  ScanSource& source_;
  ScanMapperConfig config_;
  std::unique_ptr<ScanMapper> mapper_;
};

}  // namespace metricmap
