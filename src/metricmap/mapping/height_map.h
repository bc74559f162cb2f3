#pragma once
/// \file height_map.h
/// \brief A top-down map of point counts per (cell, height bin), accumulated over frames.
///
/// Map frame: x right, y forward, z up, metres; the map is map_size x map_size cells of
/// `resolution` centred on the map origin: cell (col, row) covers
/// x in [(col - N/2) res, (col - N/2 + 1) res) and y in [(N/2 - 1 - row) res, (N/2 - row) res),
/// so row 0 is the far (forward) edge and images read like a map seen from above.
/// Height bins follow np.digitize(z, z_bins): bin 0 below z_bins[0], bin i for
/// z_bins[i-1] <= z < z_bins[i], bin len(z_bins) at or above the last edge; at least two edges.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

namespace metricmap {

struct HeightMapParams {
  double resolution = 0.05;                      ///< cell edge, metres (> 0)
  std::size_t map_size = 480;                    ///< cells per side (> 0)
  std::vector<double> z_bins{0.1, 1.0};          ///< strictly increasing edges, metres
  std::uint32_t obstacle_threshold = 1;          ///< middle-bin count that marks an obstacle
  std::size_t max_bytes = std::size_t{4} << 30;  ///< refuse maps needing more memory
};

/// \brief Counts per bin and where points went, for the frames added so far.
struct HeightMapStatistics {
  std::vector<std::uint64_t> bin_counts;  ///< points inside the map, per height bin
  std::uint64_t points_outside_map = 0;
  std::uint64_t valid_points = 0;  ///< finite points seen (= sum(bin_counts) + outside)
  std::uint64_t frames = 0;
};

/// \note Thread safety: one instance per thread.
class HeightMap {
 public:
  /// \throws std::invalid_argument for bad parameters; CapacityError when the count tensor
  /// would need more than max_bytes (the message gives the size)
  explicit HeightMap(const HeightMapParams& params);

  /// \brief Add a frame: points in its own frame, `to_map` moves them into the map frame.
  /// Every frame adds to the counts (+=).
  /// \throws std::invalid_argument unless `to_map` is a rigid transform (checkRigidTransform)
  void addFrame(const pcl::PointCloud<pcl::PointXYZ>& cloud, const Eigen::Isometry3d& to_map);

  std::size_t size() const { return params_.map_size; }
  std::size_t bins() const { return params_.z_bins.size() + 1; }
  /// \brief The bin whose count marks obstacles: the middle one, bins() / 2.
  std::size_t obstacleBin() const { return bins() / 2; }
  /// \brief Count of (row, col, bin); the tensor is row-major [row][col][bin].
  std::uint32_t count(std::size_t row, std::size_t col, std::size_t bin) const {
    return counts_[(row * params_.map_size + col) * bins() + bin];
  }
  const std::vector<std::uint32_t>& counts() const { return counts_; }
  bool obstacle(std::size_t row, std::size_t col) const {
    return count(row, col, obstacleBin()) >= params_.obstacle_threshold;
  }
  bool explored(std::size_t row, std::size_t col) const;
  std::size_t obstacleCells() const;
  std::size_t exploredCells() const;
  const HeightMapStatistics& statistics() const { return stats_; }
  const HeightMapParams& params() const { return params_; }

 private:
  HeightMapParams params_;
  std::vector<std::uint32_t> counts_;
  HeightMapStatistics stats_;
};

/// \brief Camera pose in the map frame from its height above the floor, its pitch (positive:
/// looking down) and yaw (positive: turned left), for a camera optical frame (x right, y down,
/// z forward). \throws std::invalid_argument naming a value that is not finite, or a height
/// beyond kMaxTranslation
Eigen::Isometry3d cameraToMap(double height, double pitch_rad, double yaw_rad);

/// \brief Floor-aligned pose from a floor plane n.p + d = 0 in the camera frame (|n| = 1, the
/// camera on the positive side): z = height above the plane, y = the optical axis projected
/// on the floor. \throws std::invalid_argument when the optical axis is perpendicular to the floor
Eigen::Isometry3d cameraToMapFromFloor(const Eigen::Vector3d& n, double d);

}  // namespace metricmap
