#pragma once
/// \file trajectory_order.h
/// \brief A trajectory in stamp order: raw logs deliver scans out of order (the Intel log steps
/// back 631 times), while a TUM file's stamps increase.

#include "metricmap/common/trajectory.h"

namespace metricmap {

/// \brief The poses sorted by stamp (stable).
/// \throws std::invalid_argument when the trajectory has no stamps, or two poses share a stamp
/// (naming their indices in the given order)
Trajectory inStampOrder(const Trajectory& trajectory);

}  // namespace metricmap
