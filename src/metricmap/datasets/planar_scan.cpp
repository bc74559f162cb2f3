#include "metricmap/datasets/planar_scan.h"

#include <chrono>

#include "metricmap/common/pose_2d_spatial.h"
#include "metricmap/exceptions.h"

namespace metricmap {

PlanarScan readPlanarScan(ScanSource& source, std::size_t frame, double& read_seconds) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanarScan out{source.scan(frame), std::nullopt};
  read_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!out.scan.laser) throw InputError(out.scan.name + ": not a 2D laser scan");
  if (out.scan.odometry) out.odometry = planarPose(*out.scan.odometry);
  return out;
}

}  // namespace metricmap
