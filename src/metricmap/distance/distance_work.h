#pragma once
/// \file distance_work.h
/// \brief Internals of DistanceField: its site masks and the transform passes' arrays.

#include <cstdint>
#include <vector>

#include "metricmap/distance/distance_field.h"
#include "metricmap/distance/edt_kernel.h"

namespace metricmap {

/// The site masks and the passes' arrays of the one or two transforms.
struct DistanceField::Work {
  detail::EdtShape shape;
  std::vector<std::uint8_t> site[2];  ///< obstacles; non-obstacles (signed)
  std::vector<std::uint32_t> pass1[2], pass2[2];
  std::vector<std::uint32_t> shared;  ///< both passes of either transform, when not incremental
};

}  // namespace metricmap
