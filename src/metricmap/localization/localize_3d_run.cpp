#include "metricmap/localization/localize_3d_run.h"

#include <chrono>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"

namespace metricmap {

Localize3DRun runLocalize3D(ScanSource& source, const std::vector<std::size_t>& frames,
                            const PointMap3D& map, const Localizer3DConfig& config,
                            const std::optional<Eigen::Isometry3d>& initial,
                            const Localize3DProgress& progress) {
  Localize3DRun run;
  run.localizer = std::make_unique<Localizer3D>(map, config, source.info().sensor_to_base);
  Localizer3D& localizer = *run.localizer;
  if (initial) localizer.setInitialPose(*initial);
  run.results.reserve(frames.size());
  std::vector<Eigen::Vector3f> points;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto t = std::chrono::steady_clock::now();
    const Scan scan = source.scan(frames[k]);
    run.read_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    if (scan.laser) throw InputError(scan.name + ": a 2D laser scan; a 3D map needs 3D scans");
    points.clear();
    points.reserve(scan.points.size());
    for (const pcl::PointXYZ& p : scan.points) points.emplace_back(p.x, p.y, p.z);
    run.results.push_back(localizer.localize(points));
    run.stamps.push_back(scan.stamp);
    if (progress) progress(k + 1, frames.size(), localizer);
  }
  return run;
}

}  // namespace metricmap
