#pragma once
/// \file voxel_hash_map.h
/// \brief The odometry's local map: a hash of voxels, each holding at most a few points, and
/// cut to a range window around the sensor.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "metricmap/detail/voxel_key.h"

namespace metricmap {

/// \brief Points in a voxel hash, at most `max_points` per voxel, first come first kept.
///
/// The voxels are numbered 0..voxels()-1; voxel v's points lie in one block of `max_points`
/// slots per coordinate (all x, then all y, then all z, so that distances to a voxel's points
/// are computed two at a time), and an open-addressing table (linear probing, Fibonacci
/// hashing of the packed cell) finds a voxel's number from its cell.
class VoxelHashMap {
 public:
  /// \brief Largest `max_points` accepted (every voxel reserves room for that many points).
  static constexpr int kMaxPointsPerVoxel = 1000;

  /// \throws std::invalid_argument when `voxel` is not finite > 0 or `max_points` is outside
  /// 1..kMaxPointsPerVoxel
  VoxelHashMap(double voxel, int max_points);

  /// \brief Add world points; those that fall in a full voxel are dropped.
  void add(const std::vector<Eigen::Vector3d>& points);
  /// \brief Drop every voxel whose first point lies farther than `radius` from `origin`.
  void removeFar(const Eigen::Vector3d& origin, double radius);
  /// \brief Nearest map point to `p` among the 27 voxels around it; false when none is within
  /// `max_distance`.
  bool nearest(const Eigen::Vector3d& p, double max_distance, Eigen::Vector3d& q) const;

  /// \brief The 27 voxels around a query's voxel, looked up on demand and remembered while
  /// queries stay in that voxel (valid until the map changes).
  struct Neighbourhood {
    std::uint64_t key = ~std::uint64_t{0};
    Eigen::Array3i center = Eigen::Array3i::Zero();
    std::uint32_t looked_up = 0;  ///< bit i: cells[i] is known (-1 when that voxel is empty)
    std::int32_t cells[27];       ///< i = 9 (dx + 1) + 3 (dy + 1) + (dz + 1)
  };
  /// \brief nearest() for a query that may reuse `hood`: the query's own voxel first, then
  /// outwards one axis at a time, skipping (and not looking up) every slab, row or voxel whose
  /// nearest face is farther than the best distance so far. The answer is the full scan's: ties go
  /// to the lower index. `voxel`, when given, receives the number of the voxel holding `q`.
  bool nearestCached(const Eigen::Vector3d& p, double max_distance, Neighbourhood& hood,
                     Eigen::Vector3d& q, std::int32_t* voxel = nullptr) const;

  /// \brief Number of points of voxel number `v` (0 <= v < voxels()), and its k-th point
  /// (0 <= k < voxelSize(v)), in the order they came.
  int voxelSize(std::int32_t v) const { return counts_[static_cast<std::size_t>(v)]; }
  Eigen::Vector3d voxelPoint(std::int32_t v, int k) const {
    const double* x = block(v) + k;
    return {x[0], x[stride_], x[2 * stride_]};
  }
  /// \brief Number of the voxel holding `p`, -1 when that voxel is empty.
  std::int32_t voxelOfPoint(const Eigen::Vector3d& p) const;

  /// \brief Number of voxels / points held.
  std::size_t voxels() const { return keys_.size(); }
  std::size_t points() const { return held_; }
  bool empty() const { return keys_.empty(); }
  /// \brief Bytes held by the points, the voxels' keys and counts, and the table.
  std::size_t bytes() const;
  /// \brief Every point held (for inspection and tests).
  std::vector<Eigen::Vector3d> cloud() const;
  void clear();

 private:
  struct Slot {
    std::uint64_t key;
    std::int32_t voxel;  ///< -1: empty slot
  };
  const double* block(std::int32_t v) const {
    return coords_.data() + static_cast<std::size_t>(v) * 3 * stride_;
  }
  double* block(std::int32_t v) {
    return coords_.data() + static_cast<std::size_t>(v) * 3 * stride_;
  }
  std::int32_t find(std::uint64_t key) const;
  std::int32_t findOrAdd(std::uint64_t key);
  void place(std::uint64_t key, std::int32_t voxel);
  void rebuildTable(std::size_t capacity);

  double voxel_, inv_voxel_;
  std::size_t stride_;
  std::size_t held_ = 0;
  std::vector<std::uint64_t> keys_;   // per voxel
  std::vector<std::int32_t> counts_;  // per voxel
  // Voxel v: x of its points at [3 v stride_, + counts_[v]), then y at + stride_, z at + 2 stride_.
  std::vector<double> coords_;
  std::vector<Slot> table_;  // power-of-two size, at most half full
  std::size_t mask_ = 0;
  int shift_ = 64;
};

}  // namespace metricmap
