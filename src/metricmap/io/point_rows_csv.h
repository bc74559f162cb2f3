#pragma once
/// \file point_rows_csv.h
/// \brief Points as text rows "x,y[,z]" (commas or blanks between numbers; `#` comments; an
/// optional header line): the query points of `distance --query`.

#include <string>
#include <vector>

namespace metricmap {

/// \brief Rows of 2 or 3 finite numbers (z = 0 where a row has 2); only the first non-comment
/// line may be a header (a line not starting with a number). Read whole within the memory budget.
/// \return x, y, z of each row, flattened
/// \throws InputError "FILE:LINE: ..." for a NaN, inf, garbage or a row of another length, and
/// for a file without rows
std::vector<double> readPointRows(const std::string& path);

}  // namespace metricmap
