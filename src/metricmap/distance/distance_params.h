#pragma once
/// \file distance_params.h
/// \brief Parameters of a distance field and the occupancy box it is computed over.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace metricmap {

/// \brief How never-observed voxels count: as free space or as obstacles.
enum class UnknownAs { Free, Occupied };

/// \brief What a field computes and keeps.
struct DistanceFieldParams {
  /// \brief Distances are clamped here, in metres (finite, > 0).
  double max_distance = 2.0;
  /// \brief Unknown voxels (and, for UnknownAs::Occupied, all space outside the box).
  UnknownAs unknown = UnknownAs::Free;
  /// \brief Negative inside obstacles: EDT(obstacles) - EDT(non-obstacles).
  bool signed_distance = false;
  /// \brief Keep the transform's intermediate passes (8 bytes per voxel per transform) so that
  /// update() recomputes only the lines a change reaches; without, update() recomputes all.
  bool incremental = false;
  /// \brief Threads over lines (0: all hardware threads). The result does not depend on it.
  unsigned threads = 0;
};

/// \brief Voxel states as the field stores them.
enum : std::uint8_t { kVoxelUnknown = 0, kVoxelFree = 1, kVoxelOccupied = 2 };

/// \brief A box of voxels with their states: what every builder makes and a field consumes.
/// Voxel (i, j, k) is state[(i * ny + j) * nz + k]; its centre is origin + (i, j, k) *
/// resolution. 2D maps have dimensions 2 and nz = 1. `min_key` is the map key of voxel
/// (0, 0, 0) (LogOddsMap keys; zero for other sources).
struct OccupancyBox {
  int dimensions = 3;
  std::array<std::size_t, 3> shape{{0, 0, 0}};
  double resolution = 0.0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::array<std::int64_t, 3> min_key{{0, 0, 0}};
  std::vector<std::uint8_t> state;
  std::size_t voxels() const { return shape[0] * shape[1] * shape[2]; }
};

/// \brief Bytes per voxel a field with these parameters holds (state, field, work arrays).
std::size_t distanceFieldBytesPerVoxel(const DistanceFieldParams& params);

/// \brief \throws std::invalid_argument naming max_distance unless finite and > 0
void validateDistanceFieldParams(const DistanceFieldParams& params);

}  // namespace metricmap
