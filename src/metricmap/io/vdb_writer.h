#pragma once
/// \file vdb_writer.h
/// \brief Dense voxel volumes as OpenVDB files (the sparse format planners and renderers read),
/// written through OpenVDB itself.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace metricmap {

/// \brief A dense box of float voxels, C order (k fastest): value (i, j, k) belongs to the
/// voxel whose centre is origin + (i, j, k) * resolution.
struct VdbVolume {
  std::string name = "distance";  ///< the grid's name in the file
  std::array<std::size_t, 3> shape{0, 0, 0};
  std::array<double, 3> origin{0, 0, 0};
  double resolution = 0.0;
  const std::vector<float>* values = nullptr;  ///< shape[0] * shape[1] * shape[2] values
  /// The value of every voxel not stored: voxels holding it are left inactive (sparse), and a
  /// reader gets it for them and for any point outside the box.
  float background = 0.0f;
  bool level_set = false;  ///< a signed distance (negative inside): grid class "level set"
};

/// \brief Write `volume` as one FloatGrid with a linear transform (voxel size = resolution,
/// index (0, 0, 0) at origin) and metadata "box_shape" (the dense box's extent).
/// Memory for the tree is checked against the budget before it is built.
/// \throws std::invalid_argument for an inconsistent volume; CapacityError over the budget;
/// std::runtime_error naming the file when it cannot be written
void writeVdb(const std::string& path, const VdbVolume& volume);

}  // namespace metricmap
