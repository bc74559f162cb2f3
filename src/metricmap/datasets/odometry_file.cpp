#include "metricmap/datasets/odometry_file.h"

#include "metricmap/datasets/scan_source.h"
#include "metricmap/datasets/source_odometry.h"
#include "metricmap/io/trajectory.h"

namespace metricmap {

Trajectory readOdometry(const std::string& path) {
  if (scanSourceKind(path, "auto") == "carmen") return sourceOdometry(*openScanSource(path));
  return readTrajectoryFile(path, TrajectoryFormat::Auto);
}

}  // namespace metricmap
