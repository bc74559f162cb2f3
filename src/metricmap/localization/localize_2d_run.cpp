#include "metricmap/localization/localize_2d_run.h"

#include <stdexcept>

#include "metricmap/common/pose_2d_spatial.h"
#include "metricmap/datasets/planar_scan.h"
#include "metricmap/exceptions.h"

namespace metricmap {

Localize2DRun runLocalize2D(ScanSource& source, const std::vector<std::size_t>& frames,
                            const Map2D& map, const Localizer2DConfig& config,
                            const std::optional<Pose2D>& initial,
                            const Localize2DProgress& progress) {
  Localize2DRun run;
  run.localizer =
      std::make_unique<Localizer2D>(map, config, planarPose(source.info().sensor_to_base));
  Localizer2D& localizer = *run.localizer;
  if (initial) localizer.setInitialPose(*initial);
  run.results.reserve(frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const PlanarScan p = readPlanarScan(source, frames[k], run.read_seconds);
    const Scan& scan = p.scan;
    const std::optional<Pose2D>& odometry = p.odometry;
    try {
      run.results.push_back(localizer.localize(*scan.laser, odometry));
    } catch (const std::invalid_argument& e) {
      throw InputError(scan.name + ": " + e.what());
    }
    run.stamps.push_back(scan.stamp);
    if (progress) progress(k + 1, frames.size(), localizer);
  }
  return run;
}

}  // namespace metricmap
