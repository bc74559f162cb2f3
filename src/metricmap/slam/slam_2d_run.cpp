#include "metricmap/slam/slam_2d_run.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "metricmap/common/pose_2d_spatial.h"
#include "metricmap/datasets/planar_scan.h"
#include "metricmap/exceptions.h"

namespace metricmap {

Slam2DRun runSlam2D(ScanSource& source, const std::vector<std::size_t>& frames,
                    const Slam2DConfig& config, const std::string& name,
                    const Slam2DProgress& progress) {
  Slam2DRun run;
  run.slam = std::make_unique<Slam2D>(config, planarPose(source.info().sensor_to_base));
  Slam2D& slam = *run.slam;
  Trajectory& trajectory = run.trajectory;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const PlanarScan p = readPlanarScan(source, frames[k], run.read_seconds);
    const Scan& scan = p.scan;
    const std::optional<Pose2D>& odometry = p.odometry;
    try {
      slam.addScan(*scan.laser, odometry, scan.stamp);
    } catch (const CapacityError& e) {  // the maps outgrew the budget: name the scan
      throw CapacityError(scan.name + ": " + e.what());
    } catch (const std::invalid_argument& e) {  // odometry beyond reach: name the scan
      throw InputError(scan.name + ": " + e.what());
    }
    run.scan_stamps.push_back(scan.stamp);
    if (progress) progress(k + 1, frames.size(), slam);
  }
  try {
    slam.finish();
  } catch (const CapacityError& e) {
    throw CapacityError(name + ": " + e.what());
  }
  for (const Pose2D& p : slam.trajectory()) trajectory.poses.push_back(spatialPose(p));
  if (std::all_of(run.scan_stamps.begin(), run.scan_stamps.end(),
                  [](double s) { return std::isfinite(s); }))
    trajectory.stamps = run.scan_stamps;
  return run;
}

double stampSpan(const Trajectory& trajectory) {
  if (!trajectory.hasStamps()) return 0.0;
  const auto [lo, hi] = std::minmax_element(trajectory.stamps.begin(), trajectory.stamps.end());
  return *hi - *lo;
}

}  // namespace metricmap
