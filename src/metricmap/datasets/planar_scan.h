#pragma once
/// \file planar_scan.h
/// \brief One 2D laser scan of a source with its raw odometry in the plane: what 2D SLAM and 2D
/// localisation read, scan by scan.

#include <cstddef>
#include <optional>

#include "metricmap/common/pose_2d.h"
#include "metricmap/datasets/scan_source.h"

namespace metricmap {

/// \brief A scan whose 2D beams are present, and its odometry (base -> odometry world) in
/// the plane when the source has one.
struct PlanarScan {
  Scan scan;
  std::optional<Pose2D> odometry;
};

/// \brief Scan `frame` of `source`, the reading time added to `read_seconds`.
/// \throws InputError naming the scan when it has no 2D beams
PlanarScan readPlanarScan(ScanSource& source, std::size_t frame, double& read_seconds);

}  // namespace metricmap
