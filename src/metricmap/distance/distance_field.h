#pragma once
/// \file distance_field.h
/// \brief The exact Euclidean distance field of a voxel box: distance from each voxel centre
/// to the nearest obstacle voxel's centre, clamped, optionally signed, with interpolated
/// queries and incremental updates.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "metricmap/distance/distance_params.h"

namespace metricmap {

class LogOddsMap;

/// \brief One query's answer. Outside the box (or for a non-finite point) `inside` is false and
/// distance and gradient are NaN.
struct DistanceQuery {
  bool inside = false;
  double distance = 0.0;
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();  ///< metres per metre; z = 0 in 2D
};

/// \brief What an update changed and did.
struct DistanceUpdateReport {
  std::size_t changed_voxels = 0;   ///< voxels whose obstacle status changed
  std::size_t observed_voxels = 0;  ///< voxels newly observed (unknown before)
  std::size_t outside_voxels = 0;   ///< known voxels of the map outside the box (ignored)
  std::size_t lines = 0;            ///< 1D lines recomputed, all passes and transforms
  bool full = false;                ///< recomputed everything (not incremental)
};

/// \brief An exact Euclidean distance transform over a box of voxels (Felzenszwalb and
/// Huttenlocher's separable lower envelope, exact in integer arithmetic, threaded over lines).
///
/// field()[(i * ny + j) * nz + k] is the distance in metres from the centre of voxel (i, j, k)
/// (at origin() + (i, j, k) * resolution()) to the nearest obstacle voxel's centre, clamped at
/// max_distance; voxels with no obstacle within max_distance hold max_distance. Obstacles are
/// the occupied voxels and, with UnknownAs::Occupied, the unknown ones and all space outside
/// the box. Signed: obstacle voxels hold minus the distance to the nearest non-obstacle centre
/// (clamped at -max_distance), so the interpolant's zero lies halfway between an obstacle and
/// its free neighbour.
/// \note Thread safety: const members may run concurrently; update() needs exclusive access.
class DistanceField {
 public:
  /// \brief Compute the field of `box` (moved in).
  /// \throws std::invalid_argument for bad parameters or an empty box; CapacityError when the
  /// box does not fit the memory budget or max_distance spans more than 65535 voxels
  DistanceField(OccupancyBox box, const DistanceFieldParams& params);
  ~DistanceField();
  DistanceField(DistanceField&&) noexcept;
  DistanceField& operator=(DistanceField&&) noexcept;

  int dimensions() const { return box_.dimensions; }
  const std::array<std::size_t, 3>& shape() const { return box_.shape; }
  std::size_t voxels() const { return box_.voxels(); }
  double resolution() const { return box_.resolution; }
  /// \brief Centre of voxel (0, 0, 0).
  const Eigen::Vector3d& origin() const { return box_.origin; }
  const std::array<std::int64_t, 3>& minKey() const { return box_.min_key; }
  const DistanceFieldParams& params() const { return params_; }

  /// \brief The distances, C order, voxels() floats.
  const std::vector<float>& field() const { return field_; }
  /// \brief The voxel states (kVoxelUnknown / kVoxelFree / kVoxelOccupied), C order.
  const std::vector<std::uint8_t>& states() const { return box_.state; }
  float at(std::size_t i, std::size_t j, std::size_t k) const { return field_[index(i, j, k)]; }
  bool isObstacle(std::size_t i, std::size_t j, std::size_t k) const;

  std::size_t occupiedVoxels() const;
  std::size_t obstacleVoxels() const;
  std::size_t unknownVoxels() const;
  /// \brief Voxels at max_distance (no obstacle nearer).
  std::size_t clampedVoxels() const;
  /// \brief Bytes held (field, states, work arrays).
  std::size_t bytes() const;
  /// \brief Seconds the transform alone took (last computation or update).
  double seconds() const { return seconds_; }

  /// \brief Distance at a point: trilinear (bilinear in 2D, z ignored) interpolation of the
  /// voxel-centre values, and the interpolant's analytic gradient. Points beyond the outer
  /// voxel centres (by more than 1e-9 voxel) are outside: NaN, inside = false.
  DistanceQuery query(const Eigen::Vector3d& p) const;
  /// \brief query() over `count` points of 3 doubles (x, y, z) each; distances (count) and
  /// gradients (3 count, may be null). Outside points get NaN. Threaded like the transform.
  void queryMany(const double* xyz, std::size_t count, double* distance, double* gradient) const;
  /// \brief Was the voxel holding p observed (free or occupied)? False outside the box.
  bool isObserved(const Eigen::Vector3d& p) const;
  /// \brief The centre of the obstacle voxel nearest to p among those within max_distance of
  /// p's voxel (obstacles beyond the box are taken at the box's walls' voxels, UnknownAs::
  /// Occupied). False when there is none, or p lies outside the box.
  bool nearestObstacle(const Eigen::Vector3d& p, Eigen::Vector3d& obstacle) const;

  /// \brief Bring the field up to date with `map`, whose known voxels may have changed since the
  /// field was built from it: only voxels inside the box count. With params().incremental
  /// only the 1D lines that a change reaches are recomputed; the result equals, voxel for
  /// voxel, a field built from scratch over the same box.
  /// \throws std::invalid_argument for a 2D field or a map of another resolution
  DistanceUpdateReport update(const LogOddsMap& map);
  /// \brief Replace voxel states (same box) and update as update(map) does.
  /// \param changes (index, state) pairs
  DistanceUpdateReport updateStates(
      const std::vector<std::pair<std::size_t, std::uint8_t>>& changes);

 private:
  struct Work;
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const {
    return (i * box_.shape[1] + j) * box_.shape[2] + k;
  }
  bool obstacleState(std::uint8_t s) const {
    return s == kVoxelOccupied || (s == kVoxelUnknown && params_.unknown == UnknownAs::Occupied);
  }
  /// Run the transforms over every line, or from the given pass-1 lines (i * ny + j) on
  /// (incremental only).
  void compute(const std::vector<std::size_t>* pass1_lines, std::size_t& lines);
  float value(std::uint32_t d2) const;

  OccupancyBox box_;
  DistanceFieldParams params_;
  std::vector<float> field_;
  std::unique_ptr<Work> work_;
  std::uint32_t cap_ = 1;
  double seconds_ = 0.0;
};

}  // namespace metricmap
