#pragma once
/// \file lines_json.h
/// \brief Read back the segments that `metricmap lines --format json` wrote.

#include <string>
#include <vector>

#include "metricmap/common/segment_2d.h"

namespace metricmap {

/// \brief The segments (start, end) of scan `scan` in the JSON of `metricmap lines`.
/// \throws InputError naming the file when it is not that JSON (nesting deeper than 32 levels
/// is refused while parsing) or has no such scan
std::vector<Segment2D> readLineSegmentsJson(const std::string& path, long long scan);

}  // namespace metricmap
