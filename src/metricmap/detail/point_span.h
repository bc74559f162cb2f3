#pragma once
/// \file point_span.h
/// \brief A non-owning view of x, y, z in any PCL point type, so kernels compile once.

#include <cstddef>

namespace metricmap {

/// \brief Strided view over the x, y, z floats of a point array, optionally through indices.
///
/// PCL point types keep x, y, z as the first three floats; `stride` is sizeof(PointT).
struct PointSpan {
  const float* base = nullptr;   ///< x of point 0
  std::size_t stride = 0;        ///< bytes between consecutive points
  const int* indices = nullptr;  ///< optional subset (pcl::Indices data)
  std::size_t size = 0;          ///< number of points (or indices) in the view

  /// \brief Position in the underlying array of the i-th point of the view.
  std::size_t sourceIndex(std::size_t i) const {
    return indices ? static_cast<std::size_t>(indices[i]) : i;
  }
  /// \brief Pointer to x of the i-th point of the view (y, z follow).
  const float* at(std::size_t i) const {
    return reinterpret_cast<const float*>(reinterpret_cast<const char*>(base) +
                                          sourceIndex(i) * stride);
  }
};

}  // namespace metricmap
