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
  /// \brief The 27 voxels around a query's voxel, looked up on demand and remembered while
  /// queries stay in that voxel (the pointers stay valid until the map changes).
  struct Neighbourhood {
    std::uint64_t key = ~std::uint64_t{0};
    Eigen::Array3i center = Eigen::Array3i::Zero();
    std::uint32_t looked_up = 0;  ///< bit i: cells[i] is known (null when that voxel is empty)
    const Cell* cells[27];        ///< i = 9 (dx + 1) + 3 (dy + 1) + (dz + 1)
  };
  /// \brief nearest() for a query that may reuse `hood`: the query's own voxel first, then
  /// outwards one axis at a time, skipping (and not looking up) every slab, row or voxel whose
  /// nearest face is farther than the best distance so far. The answer is the full scan's: ties go
  /// to the lower index.
  bool nearestCached(const Eigen::Vector3d& p, double max_distance, Neighbourhood& hood,
                     Eigen::Vector3d& q) const;

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
