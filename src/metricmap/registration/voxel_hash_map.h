#pragma once
/// \file voxel_hash_map.h
/// \brief The odometry's local map: a hash of voxels, each holding at most a few points, and
/// cut to a range window around the sensor.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "metricmap/registration/voxel_key.h"

namespace metricmap {

/// \brief Points in a voxel hash, at most `max_points` per voxel, first come first kept.
class VoxelHashMap {
 public:
  /// \throws std::invalid_argument when `voxel` is not finite > 0 or `max_points` < 1
  VoxelHashMap(double voxel, int max_points);

  /// \brief Add world points; those that fall in a full voxel are dropped.
  void add(const std::vector<Eigen::Vector3d>& points);
  /// \brief Drop every voxel whose first point lies farther than `radius` from `origin`.
  void removeFar(const Eigen::Vector3d& origin, double radius);
  /// \brief Nearest map point to `p` among the 27 voxels around it; false when none is within
  /// `max_distance`.
  bool nearest(const Eigen::Vector3d& p, double max_distance, Eigen::Vector3d& q) const;

  using Cell = std::vector<Eigen::Vector3d>;
  /// \brief A neighbour's voxel relative to the query's: -1, 0 or +1 per axis.
  struct Offset {
    std::int8_t d[3];
  };
  /// \brief Key of the voxel holding `p`.
  std::uint64_t keyOf(const Eigen::Vector3d& p) const {
    const Eigen::Array3i c = voxelOf(p, inv_voxel_);
    return packVoxel(c.x(), c.y(), c.z());
  }
  /// \brief The non-empty voxels among the 27 around `p` into `out`; returns how many. The
  /// pointers stay valid until the map changes.
  int neighbours(const Eigen::Vector3d& p, const Cell* out[27], Offset offsets[27]) const;
  /// \brief The nearest point within max_distance of `p` in `cells` (from neighbours() of a
  /// point in the same voxel as `p`), scanned in order; a cell whose box is farther from `p`
  /// than the best distance so far is skipped (it cannot hold a nearer point, so the answer is
  /// the one a full scan gives).
  bool nearestIn(const Cell* const* cells, const Offset* offsets, int n, const Eigen::Vector3d& p,
                 double max_distance, Eigen::Vector3d& q) const;

  /// \brief Points of the voxel holding `p` (nullptr when that voxel is empty).
  const std::vector<Eigen::Vector3d>* voxelPoints(const Eigen::Vector3d& p) const;

  /// \brief Number of voxels / points held.
  std::size_t voxels() const { return map_.size(); }
  std::size_t points() const { return points_; }
  bool empty() const { return map_.empty(); }
  /// \brief Bytes held by the points and the hash nodes (an estimate from the sizes).
  std::size_t bytes() const;
  /// \brief Every point held (for inspection and tests).
  std::vector<Eigen::Vector3d> cloud() const;
  void clear() {
    map_.clear();
    points_ = 0;
  }

 private:
  double voxel_, inv_voxel_;
  int max_points_;
  std::size_t points_ = 0;
  std::unordered_map<std::uint64_t, std::vector<Eigen::Vector3d>, VoxelKeyHash> map_;
};

}  // namespace metricmap
