#pragma once
/// \file log_odds_map.h
/// \brief A probabilistic 3D voxel map: log-odds per voxel, updated by casting every beam from
/// the sensor through free voxels to its endpoint (OctoMap's sensor model).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <pcl/point_cloud.h>
#include <Eigen/Core>

#include "metricmap/detail/voxel_key.h"
#include "metricmap/occupancy/block_table.h"
#include "metricmap/occupancy/log_odds_params.h"

namespace metricmap {

/// \brief Occupied (probability >= threshold), free (below), or never observed.
enum class VoxelState { Unknown, Free, Occupied };

/// \brief What one insertScan did.
struct ScanInsertReport {
  std::size_t points = 0;       ///< points in the cloud
  std::size_t non_finite = 0;   ///< skipped: a NaN/Inf coordinate
  std::size_t beams = 0;        ///< beams cast (finite points)
  std::size_t beams_cut = 0;    ///< beams longer than max_range, cut there, no hit
  std::size_t hit_voxels = 0;   ///< distinct voxels updated as hits
  std::size_t miss_voxels = 0;  ///< distinct voxels updated as misses (hits excluded)
};

/// \brief Bytes of the map: blocks in use and the hash (`bytes`), per known voxel, and the
/// block capacity reserved ahead (allocated, mostly untouched).
struct LogOddsMemory {
  std::size_t blocks = 0, known_voxels = 0, bytes = 0, reserved_bytes = 0;
  double bytes_per_known_voxel = 0.0;
};

/// \brief Probabilistic occupancy of world-aligned voxels (key = floor(p / resolution), 64-bit),
/// stored sparsely in hashed blocks of 8^3 voxels.
///
/// insertScan follows OctoMap's insertPointCloud (lazy evaluation off, no discretisation):
/// every voxel on a beam between the sensor's voxel and the endpoint's is a miss, the
/// endpoint's voxel a hit; a beam longer than max_range is cut there and marks no hit; within
/// one scan each voxel is updated once and a hit wins over a miss. Log-odds are float, clamped.
/// An insert may cast its beams on several threads (setThreads): of n threads, thread t casts
/// points t, t + n, t + 2n, ... (a share of every part of the scan); the shares' voxel sets are
/// united and the map is updated once, in block-key order — the same map, in the same order,
/// for every thread count.
/// \note Thread safety: const members may run concurrently; inserts need exclusive access.
class LogOddsMap {
 public:
  /// \throws std::invalid_argument naming a bad parameter (see validateLogOddsParams)
  explicit LogOddsMap(const LogOddsParams& params = LogOddsParams());

  /// \brief Cast the beams of a cloud whose points are in the world frame, from `sensor_origin`.
  /// Points with a NaN/Inf coordinate are skipped and counted.
  /// \throws CapacityError when a point or the origin lies outside the key space; the map is
  /// then unchanged
  /// \throws std::invalid_argument for a non-finite origin
  template <typename PointT>
  ScanInsertReport insertScan(const pcl::PointCloud<PointT>& cloud,
                              const Eigen::Vector3f& sensor_origin) {
    return insertRaw(cloud.empty() ? nullptr : &cloud.points[0].x, sizeof(PointT), cloud.size(),
                     sensor_origin, nullptr);
  }

  /// \brief Cast the beams of a cloud in the sensor frame whose pose is the cloud's own
  /// `sensor_origin_` / `sensor_orientation_` (PCD VIEWPOINT): p_world = R p + t, origin t.
  template <typename PointT>
  ScanInsertReport insertScan(const pcl::PointCloud<PointT>& cloud) {
    const Eigen::Matrix3f r = cloud.sensor_orientation_.normalized().toRotationMatrix();
    const Eigen::Vector3f t = cloud.sensor_origin_.template head<3>();
    const float pose[12] = {r(0, 0), r(0, 1), r(0, 2), t.x(),   r(1, 0), r(1, 1),
                            r(1, 2), t.y(),   r(2, 0), r(2, 1), r(2, 2), t.z()};
    return insertRaw(cloud.empty() ? nullptr : &cloud.points[0].x, sizeof(PointT), cloud.size(), t,
                     pose);
  }

  /// \brief Raw form: `count` points of 3 floats starting at `xyz`, `stride_bytes` apart;
  /// `pose` (row-major 3x4, or null) maps them to the world.
  ScanInsertReport insertRaw(const float* xyz, std::size_t stride_bytes, std::size_t count,
                             const Eigen::Vector3f& sensor_origin, const float* pose);

  /// \brief Add the log-odds of every voxel of `other` (clamped). Equals one map built from
  /// both maps' scans wherever no clamping occurred.
  /// \throws std::invalid_argument when resolutions or sensor models differ
  void merge(const LogOddsMap& other);

  /// \brief Visit every block of 8^3 voxels holding a known voxel: its packed block key
  /// (packVoxelKey of voxel key >> 3), kBlockWords words of known bits (voxel i = x + 8 y +
  /// 64 z inside the block) and its kBlockVoxels log-odds (meaningful where known).
  void forEachBlock(
      const std::function<void(std::uint64_t, const std::uint64_t*, const float*)>& visit) const;

  /// \brief Merge a block as merge() does, voxel by voxel: `values` holds one log-odds per set
  /// bit of `known`, in bit order. The caller checks the key, the bits and that values are
  /// finite (log_odds_transfer.cpp does).
  void mergeBlock(std::uint64_t block_key, const std::uint64_t* known, const float* values);

  /// \brief Set a voxel's log-odds as given (finite), marking it known. Used by readers.
  /// \throws CapacityError outside the key space; std::invalid_argument for NaN/Inf
  void setLogOdds(const VoxelKey& key, float log_odds);

  /// \brief The voxel holding `p`: floor(p * (1 / resolution)) in double, as OctoMap does.
  VoxelKey keyOf(const Eigen::Vector3d& p) const;
  /// \brief Centre of a voxel.
  Eigen::Vector3d centerOf(const VoxelKey& key) const;

  /// \brief Log-odds of a voxel, or nothing when it was never observed.
  std::optional<float> logOdds(const VoxelKey& key) const;
  VoxelState state(const VoxelKey& key) const;
  VoxelState state(const Eigen::Vector3d& p) const { return state(keyOf(p)); }
  /// \brief Occupancy probability; 0.5 for an unknown voxel.
  double probability(const VoxelKey& key) const;
  double probability(const Eigen::Vector3d& p) const { return probability(keyOf(p)); }

  /// \brief Visit every known voxel (block order): key and log-odds.
  void forEachKnown(const std::function<void(const VoxelKey&, float)>& visit) const;

  std::size_t knownVoxels() const { return known_; }
  std::size_t occupiedVoxels() const;
  std::size_t freeVoxels() const { return known_ - occupiedVoxels(); }
  /// \brief Smallest and largest key of the known voxels; false when the map is empty.
  bool keyBounds(VoxelKey& min_key, VoxelKey& max_key) const;
  LogOddsMemory memory() const;

  const LogOddsParams& params() const { return params_; }
  double resolution() const { return params_.resolution; }
  float hitLogOdds() const { return hit_; }
  float missLogOdds() const { return miss_; }
  float clampMinLogOdds() const { return clamp_min_; }
  float clampMaxLogOdds() const { return clamp_max_; }
  /// \brief Occupied iff log-odds >= this.
  float thresholdLogOdds() const { return threshold_; }
  bool isOccupied(float log_odds) const { return log_odds >= threshold_; }

  /// \brief Forget every voxel.
  void clear();

  /// \brief Threads that cast a scan's beams (0: all hardware threads; 1 by default). Scans
  /// of fewer than 8192 points per thread use fewer threads. The result does not depend on it.
  void setThreads(unsigned threads) { threads_ = threads; }
  unsigned threads() const { return threads_; }

 private:
  detail::VoxelBlock& blockFor(std::uint64_t block_key);
  /// Add the known voxels of `known` into `blk`; value_of(index) gives each one's log-odds,
  /// called in ascending index order.
  template <typename NextValue>
  void mergeInto(detail::VoxelBlock& blk, const std::uint64_t* known, NextValue value_of);
  void applyScan(ScanInsertReport& report);

  LogOddsParams params_;
  float hit_, miss_, clamp_min_, clamp_max_, threshold_;
  std::vector<detail::VoxelBlock> blocks_;
  detail::BlockHashIndex index_;
  std::size_t known_ = 0;
  detail::ScanUpdate scratch_;
  std::vector<detail::ScanUpdate> thread_scratch_;  ///< threads 1.. of a threaded insert
  std::vector<std::uint32_t> order_;                ///< the scan's blocks in key order
  std::vector<std::uint32_t> targets_;              ///< their map blocks, in that order
  unsigned threads_ = 1;
};

}  // namespace metricmap
