#pragma once
/// \file localizer_3d.h
/// \brief 3D localisation of a LiDAR in a fixed point map:
/// - global (no pose yet, or lost): the scan is levelled by its ground plane and described by
///   its bird's-eye Scan Context (place_descriptor_3d.h); the descriptor is compared, over every
///   yaw, with those of the map's candidate places (map_places_3d.h); the `global_candidates`
///   nearest places (one per neighbourhood) give guesses that the loop verification of slam3d
///   aligns to the map around the place by ICP and tests for overlap. The best verified pose (by
///   structure overlap) is accepted when it exceeds that of the best *distinct* pose by
///   `global_min_margin`; otherwise the scan is "ambiguous" (or "not found" when none passes);
/// - tracking: each later scan is aligned to the whole map from the constant-velocity
///   prediction (point-to-point ICP, coarse then fine); a scan whose overlap with the map falls
///   below `track_min_overlap`, or whose pose runs more than `track_max_correction` from the
///   prediction, is weak (not reported); after `lost_after_weak_scans` weak scans in a row the
///   robot is lost and the global search takes over (a kidnapped robot is found again).
/// Poses are the base's in the map's frame.

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "metricmap/localization/localization_status.h"
#include "metricmap/localization/localizer_3d_config.h"
#include "metricmap/localization/point_map_3d.h"

namespace metricmap {

/// \brief The result for one scan.
struct Localization3D {
  LocalizationStatus status = LocalizationStatus::NotFound;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< base -> map, when localised()
  /// Tracking: overlap with the map; global search: the best pose's structure overlap.
  double score = 0.0;
  /// Global search: the best's structure overlap minus the best distinct pose's (0 when none).
  double margin = 0.0;
  bool localised() const {
    return status == LocalizationStatus::Fixed || status == LocalizationStatus::Tracked;
  }
};

/// \brief Counts and time per phase (seconds, wall clock).
struct Localizer3DStats {
  std::size_t scans = 0, localised = 0;
  std::size_t global_searches = 0, fixes = 0, ambiguous = 0, losses = 0;
  std::size_t places = 0;                ///< candidate places of the map
  std::size_t candidates = 0;            ///< guesses verified by the global searches
  std::optional<std::size_t> first_fix;  ///< scan index (0-based, in the order given)
  double setup_seconds = 0.0;            ///< the map's hash and places
  double global_seconds = 0.0, track_seconds = 0.0;
};

/// \brief The localiser. Not thread-safe; the map is copied into its own structures.
class Localizer3D {
 public:
  /// \throws std::invalid_argument naming a bad configuration value or an empty map;
  /// CapacityError when the map's structures do not fit in the memory budget
  Localizer3D(const PointMap3D& map, const Localizer3DConfig& config,
              const Eigen::Isometry3d& sensor_to_base = Eigen::Isometry3d::Identity());
  ~Localizer3D();
  Localizer3D(const Localizer3D&) = delete;
  Localizer3D& operator=(const Localizer3D&) = delete;

  /// \brief Start from a pose the user knows (base -> map): for the next scan it replaces the
  /// place search (levelled by the scan's ground, its heading searched as in tracking, then the
  /// same verification); when that fails, the global search takes over.
  /// \throws std::invalid_argument if not finite, not a rotation, or outside the map's box
  /// grown by the descriptor's radius
  void setInitialPose(const Eigen::Isometry3d& pose);

  /// \brief Localise the next scan (sensor frame; NaN points skipped).
  Localization3D localize(const std::vector<Eigen::Vector3f>& scan);

  /// \brief The status of the last scan (NotFound before any).
  LocalizationStatus status() const;
  const Localizer3DStats& stats() const;
  const Localizer3DConfig& config() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace metricmap
