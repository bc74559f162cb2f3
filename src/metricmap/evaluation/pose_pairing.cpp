#include "metricmap/evaluation/pose_pairing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "metricmap/common/format_number.h"

namespace metricmap {

std::size_t nearestStamp(const std::vector<double>& stamps, double t, double max_diff) {
  const auto it = std::lower_bound(stamps.begin(), stamps.end(), t);
  std::size_t best = stamps.size();
  double best_diff = max_diff;
  auto consider = [&](std::vector<double>::const_iterator c) {
    const double d = std::abs(*c - t);
    if (d <= best_diff && (best == stamps.size() || d < best_diff)) {
      best = static_cast<std::size_t>(c - stamps.begin());
      best_diff = d;
    }
  };
  if (it != stamps.begin()) consider(std::prev(it));
  if (it != stamps.end()) consider(it);
  return best;
}

void requireIncreasingStamps(const Trajectory& trajectory, const char* what) {
  if (trajectory.stamps.size() != trajectory.poses.size()) {
    throw std::invalid_argument(std::string(what) + ": " +
                                std::to_string(trajectory.stamps.size()) + " stamps for " +
                                std::to_string(trajectory.poses.size()) + " poses");
  }
  for (std::size_t i = 1; i < trajectory.stamps.size(); ++i) {
    if (!(trajectory.stamps[i] > trajectory.stamps[i - 1])) {
      throw std::invalid_argument(std::string(what) + ": stamp " + std::to_string(i) +
                                  " is not after the one before");
    }
  }
}

PosePairs pairPoses(const Trajectory& estimate, const Trajectory& reference, double max_time_diff) {
  PosePairs pairs;
  if (estimate.hasStamps() && reference.hasStamps()) {
    requireIncreasingStamps(estimate, "estimate");
    requireIncreasingStamps(reference, "reference");
    pairs.mode = PairingMode::Stamps;
    pairs.max_time_diff = max_time_diff;
    const bool estimate_shorter = estimate.size() <= reference.size();
    const Trajectory& shorter = estimate_shorter ? estimate : reference;
    const Trajectory& longer = estimate_shorter ? reference : estimate;
    for (std::size_t i = 0; i < shorter.size(); ++i) {
      const std::size_t j = nearestStamp(longer.stamps, shorter.stamps[i], max_time_diff);
      if (j == longer.size()) continue;
      pairs.estimate.push_back(estimate_shorter ? i : j);
      pairs.reference.push_back(estimate_shorter ? j : i);
    }
    if (pairs.size() < 2) {
      throw std::invalid_argument(
          std::to_string(pairs.size()) + " pose(s) of the estimate and the reference have time " +
          "stamps within " + formatNumber(max_time_diff) + " s of each other; 2 or more needed");
    }
    return pairs;
  }
  if (estimate.size() != reference.size()) {
    throw std::invalid_argument("the estimate has " + std::to_string(estimate.size()) +
                                " poses and the reference " + std::to_string(reference.size()) +
                                ": pairing by index needs as many (pairing by time needs "
                                "stamps in both, TUM form)");
  }
  if (estimate.size() < 2) throw std::invalid_argument("fewer than 2 poses to compare");
  pairs.mode = PairingMode::Index;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    pairs.estimate.push_back(i);
    pairs.reference.push_back(i);
  }
  return pairs;
}

}  // namespace metricmap
