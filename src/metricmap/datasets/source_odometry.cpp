#include "metricmap/datasets/source_odometry.h"

#include <cmath>

#include "metricmap/exceptions.h"

namespace metricmap {

Trajectory sourceOdometry(ScanSource& source) {
  Trajectory t;
  for (std::size_t i = 0; i < source.size(); ++i) {
    const Scan scan = source.scan(i);
    if (!scan.odometry) throw InputError(scan.name + ": no odometry with this scan");
    if (!std::isfinite(scan.stamp)) throw InputError(scan.name + ": no time stamp");
    t.poses.push_back(*scan.odometry);
    t.stamps.push_back(scan.stamp);
  }
  if (t.poses.empty()) throw InputError(source.info().path + ": no scans");
  return t;
}

}  // namespace metricmap
