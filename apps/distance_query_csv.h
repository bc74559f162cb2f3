#pragma once
/// \file distance_query_csv.h
/// \brief The answers of `distance --query` as CSV.

#include <string>
#include <vector>

#include "metricmap/distance/distance_field.h"

namespace metricmap::cli {

/// \brief One line per point: x,y,z,distance,gx,gy,gz,inside (nan outside the box).
std::string queryCsv(const DistanceField& field, const std::vector<double>& xyz);

}  // namespace metricmap::cli
