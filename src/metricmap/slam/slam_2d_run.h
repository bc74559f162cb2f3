#pragma once
/// \file slam_2d_run.h
/// \brief Slam2D over the scans of a planar source (a CARMEN log): each scan's beams, raw
/// odometry and stamp, then the final optimisation and map.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "metricmap/common/trajectory.h"
#include "metricmap/slam/slam_2d.h"

namespace metricmap {

class ScanSource;

/// \brief Called after each scan: (scans done, scans in all, the SLAM so far).
using Slam2DProgress = std::function<void(std::size_t, std::size_t, const Slam2D&)>;

/// \brief A finished run.
struct Slam2DRun {
  std::unique_ptr<Slam2D> slam;
  /// \brief The optimised pose of every scan with its stamp; no stamps when any scan has none.
  Trajectory trajectory;
  /// \brief Every scan's stamp as read, in order (NaN where a scan has none).
  std::vector<double> scan_stamps;
  double read_seconds = 0.0;  ///< reading the scans from the source
};

/// \brief Run Slam2D (`config`, with the source's laser offset as sensor_to_base) over the
/// scans `frames` of `source`, then finish it. Messages name the scan, or `name` for the
/// final step.
/// \throws InputError for a scan that is not a 2D laser scan, or whose odometry the SLAM
/// refuses; CapacityError (naming the scan, or `name`) when the maps outgrow the memory budget
Slam2DRun runSlam2D(ScanSource& source, const std::vector<std::size_t>& frames,
                    const Slam2DConfig& config, const std::string& name,
                    const Slam2DProgress& progress = {});

/// \brief The span of the trajectory's stamps (last minus first, s); 0 without stamps.
double stampSpan(const Trajectory& trajectory);

}  // namespace metricmap
