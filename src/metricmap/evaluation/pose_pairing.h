#pragma once
/// \file pose_pairing.h
/// \brief Which estimated pose is compared with which reference pose.

#include <cstddef>
#include <vector>

#include "metricmap/common/trajectory.h"

namespace metricmap {

/// \brief Index: pose i with pose i; Stamps: by nearest time stamp.
enum class PairingMode { Index, Stamps };

/// \brief Pairs (estimate[k], reference[k]) of pose indices, in the estimate's order.
struct PosePairs {
  PairingMode mode = PairingMode::Index;
  double max_time_diff = 0.0;  ///< seconds, for Stamps
  std::vector<std::size_t> estimate;
  std::vector<std::size_t> reference;

  std::size_t size() const { return estimate.size(); }
};

/// \brief Pair the poses of two trajectories.
///
/// When both have stamps, by stamps as evo's associate_trajectories: for every stamp of the
/// shorter trajectory (the estimate when both are as long), the nearest stamp of the other
/// one, kept when they differ by at most `max_time_diff`. Otherwise by index, which needs
/// both to have the same number of poses.
/// \throws std::invalid_argument when the counts differ (by index), a trajectory's stamps are
/// not one per pose or do not increase, or fewer than 2 pairs are found
PosePairs pairPoses(const Trajectory& estimate, const Trajectory& reference,
                    double max_time_diff = 0.01);

/// \brief The index of the stamp in `stamps` (increasing) nearest to `t`, or stamps.size()
/// when none is within `max_diff` (ties: the earlier stamp).
std::size_t nearestStamp(const std::vector<double>& stamps, double t, double max_diff);

/// \brief \throws std::invalid_argument naming `what` unless `trajectory` has one stamp per
/// pose, strictly increasing.
void requireIncreasingStamps(const Trajectory& trajectory, const char* what);

}  // namespace metricmap
