#pragma once
/// \file log_odds_object.h
/// \brief The object behind metricmap.LogOddsMap, shared by the binding files that take one.

#include <limits>
#include <memory>

#include "metricmap/occupancy/log_odds_map.h"
#include "object_lock.h"

namespace metricmap::python {

/// The Python object: the map, replaced by a copy with another max_range when a call asks for
/// one (the library keeps max_range in the map's parameters).
struct PyLogOddsMap {
  std::unique_ptr<LogOddsMap> map;
  mutable ObjectMutex mutex;  ///< serialises the object's calls

  void useMaxRange(double max_range) {
    if (!(max_range > 0.0)) max_range = std::numeric_limits<double>::infinity();  // OctoMap: -1
    if (map->params().max_range == max_range) return;
    LogOddsParams p = map->params();
    p.max_range = max_range;
    auto copy = std::make_unique<LogOddsMap>(p);
    copy->merge(*map);  // a fresh map takes every voxel's log-odds as it is
    map = std::move(copy);
  }
};

}  // namespace metricmap::python
