#pragma once
/// \file kitti_mapping.h
/// \brief A KITTI odometry sequence through ScanMapper: the chosen frames read in the order given,
/// each fused at its pose-file pose in the chosen world (optionally perturbed, for registration
/// experiments) or at the pose LidarOdometry gives, with one report per frame and the totals.
/// What `metricmap kitti` runs.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/sequence/scan_mapper.h"

namespace metricmap {

/// \brief What to map and how.
struct KittiMappingOptions {
  KittiSequence sequence;           ///< root and sequence number
  std::vector<std::size_t> frames;  ///< mapped in this order
  KittiWorld world = KittiWorld::Camera;
  /// \brief The mapper; with `odometry` on, the poses come from the scans and no pose file is
  /// read (`odometry_origin` is set here from the world).
  ScanMapperConfig mapper;
  /// \brief Each pose after the first frame's moved by this many metres and turned by this many
  /// degrees, in random directions drawn from `seed` (perturbPose); 0, 0: as given.
  double perturb_translation = 0.0, perturb_rotation_deg = 0.0;
  unsigned seed = 1;
};

/// \brief Sums over the frames mapped so far.
struct KittiMappingTotals {
  std::uint64_t points_read = 0, points_kept = 0, points_mapped = 0;
  double load_s = 0.0;       ///< reading the scans
  double transform_s = 0.0;  ///< moving them to the world and registering them
  double map_s = 0.0;        ///< counting them in the 2D map
};

/// \brief What a run gave.
struct KittiMappingRun {
  std::unique_ptr<ScanMapper> mapper;     ///< the maps, the poses used
  std::vector<FrameReport> reports;       ///< one per frame
  std::vector<OdometryResult> odometry;   ///< one per frame with odometry, else empty
  std::vector<Eigen::Isometry3d> truths;  ///< the pose file's scan -> world poses (no odometry)
  KittiMappingTotals totals;
  Eigen::Isometry3d tr = Eigen::Isometry3d::Identity();  ///< calib.txt's Tr
  KittiWorld world = KittiWorld::Camera;

  /// \brief The poses used, as KITTI's pose files hold them (kittiPoseOfScan).
  std::vector<Eigen::Isometry3d> posesOfScans() const;
  /// \brief Registration seconds summed over the frames.
  double registerSeconds() const;
  /// \brief 3D occupancy seconds summed over the frames.
  double occupancySeconds() const;
};

/// \brief Called after each frame with (frames done, frames to do, the totals so far).
using KittiMappingObserver =
    std::function<void(std::size_t done, std::size_t total, const KittiMappingTotals& totals)>;

/// \brief Map the frames: every scan is checked to exist before any work, then calib.txt and
/// (without odometry) the pose file up to the highest frame are read.
/// \throws InputError naming the file for a missing frame, a bad calib or pose file, or a scan
/// that cannot be read or registered; std::invalid_argument for a bad configuration
KittiMappingRun mapKittiSequence(const KittiMappingOptions& options,
                                 const KittiMappingObserver& observer = {});

}  // namespace metricmap
