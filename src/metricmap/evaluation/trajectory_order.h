#pragma once
/// \file trajectory_order.h
/// \brief A trajectory in stamp order: raw logs deliver scans out of order (the Intel log steps
/// back 631 times), while a TUM file's stamps increase.

#include <cstddef>
#include <vector>

#include "metricmap/common/trajectory.h"

namespace metricmap {

/// \brief The indices of the poses in stamp order (stable): entry k is the index in
/// `trajectory` of the k-th earliest pose.
/// \throws std::invalid_argument when the trajectory has no stamps, or two poses share a stamp
/// (naming their indices in the given order)
std::vector<std::size_t> stampOrder(const Trajectory& trajectory);

/// \brief The poses sorted by stamp (stable).
/// \throws std::invalid_argument when the trajectory has no stamps, or two poses share a stamp
/// (naming their indices in the given order)
Trajectory inStampOrder(const Trajectory& trajectory);

}  // namespace metricmap
