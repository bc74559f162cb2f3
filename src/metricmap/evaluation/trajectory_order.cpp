#include "metricmap/evaluation/trajectory_order.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace metricmap {

std::vector<std::size_t> stampOrder(const Trajectory& t) {
  if (!t.hasStamps() || t.stamps.size() != t.size())
    throw std::invalid_argument("a trajectory in stamp order needs one stamp per pose");
  std::vector<std::size_t> order(t.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return t.stamps[a] < t.stamps[b]; });
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (t.stamps[order[k]] == t.stamps[order[k - 1]])
      throw std::invalid_argument("poses " + std::to_string(order[k - 1]) + " and " +
                                  std::to_string(order[k]) + " have the same stamp");
  }
  return order;
}

Trajectory inStampOrder(const Trajectory& t) {
  const std::vector<std::size_t> order = stampOrder(t);
  Trajectory sorted;
  sorted.stamps.reserve(t.size());
  sorted.poses.reserve(t.size());
  for (std::size_t k : order) {
    sorted.stamps.push_back(t.stamps[k]);
    sorted.poses.push_back(t.poses[k]);
  }
  return sorted;
}

}  // namespace metricmap
