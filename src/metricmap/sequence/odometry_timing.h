#pragma once
/// \file odometry_timing.h
/// \brief How long an odometry run's registrations took, as `metricmap odometry` reports it.

#include <vector>

#include "metricmap/sequence/odometry_run.h"

namespace metricmap {

/// \brief The median registration time (ms, reading excluded) of `frames`: the upper of the two
/// middle values for an even count; 0 for none.
double medianFrameMs(const std::vector<OdometryFrame>& frames);

}  // namespace metricmap
