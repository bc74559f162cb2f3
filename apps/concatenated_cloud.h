#pragma once
/// \file concatenated_cloud.h
/// \brief Several cloud files as one input.

#include <cstddef>
#include <string>
#include <vector>

#include "cli_common.h"

namespace metricmap::cli {

/// \brief files[first, last) loaded (loadTimed: warnings to stderr) and concatenated in order
/// into the first one's cloud; `seconds` is their loading time. An empty range gives an empty
/// cloud.
LoadedCloud loadConcatenated(const std::vector<std::string>& files, std::size_t first,
                             std::size_t last);

}  // namespace metricmap::cli
