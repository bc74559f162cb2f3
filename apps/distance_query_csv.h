#pragma once
/// \file distance_query_csv.h
/// \brief The query points of `distance --query` (CSV rows x,y[,z]) and the answers' CSV.

#include <string>
#include <vector>

#include "metricmap/distance/distance_field.h"

namespace metricmap::cli {

/// \brief Rows of 2 or 3 numbers separated by commas or spaces; a first line that is not
/// numeric is a header. \throws InputError "FILE:LINE: ..." for a NaN, inf, garbage or a
/// row of another length; for a file without rows
std::vector<double> readQueryPoints(const std::string& path);

/// \brief One line per point: x,y,z,distance,gx,gy,gz,inside (nan outside the box).
std::string queryCsv(const DistanceField& field, const std::vector<double>& xyz);

}  // namespace metricmap::cli
