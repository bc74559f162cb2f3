#pragma once
/// \file localizer_2d.h
/// \brief 2D localisation of a laser robot in a fixed map:
/// - global (no pose yet, or lost): the exact branch-and-bound of the slam module over the whole
///   map and every heading finds the best pose of the scan; it is accepted when its refined
///   score reaches `global_min_score` and its search score exceeds that of the best *distinct*
///   pose (the same search with the best's neighbourhood excluded) by `global_min_margin`;
///   otherwise the scan is "ambiguous" (a symmetric building, or a map of somewhere else) or
///   "not found";
/// - tracking: each later scan is matched against the map from the motion prediction (the
///   odometry's motion since the last scan, or the last scan's motion without odometry): a
///   correlative search in a small window, then Gauss-Newton (the slam module's scan matcher);
/// - loss: a scan scoring below `track_min_score` is weak (its pose is not reported); after
///   `lost_after_weak_scans` weak scans in a row the robot is lost and the global search takes
///   over (a kidnapped robot is found again).
/// Poses are the robot's (base) in the map's world frame.

#include <cstddef>
#include <memory>
#include <optional>

#include "metricmap/common/map_2d.h"
#include "metricmap/common/pose_2d.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/localization/localization_status.h"
#include "metricmap/localization/localizer_2d_config.h"

namespace metricmap {

/// \brief The result for one scan.
struct Localization2D {
  LocalizationStatus status = LocalizationStatus::NotFound;
  Pose2D pose;         ///< map frame; meaningful when localised() (and for Weak)
  double score = 0.0;  ///< refined nearest-cell score (0 when nothing was matched)
  /// Global search: the best's search score minus the best distinct pose's (0 when none).
  double margin = 0.0;
  /// Global search: the share of the scan's beams that pass through a wall of the map at the
  /// best pose (0 when not computed).
  double crossing = 0.0;
  bool localised() const {
    return status == LocalizationStatus::Fixed || status == LocalizationStatus::Tracked;
  }
};

/// \brief Counts and time per phase (seconds, wall clock).
struct Localizer2DStats {
  std::size_t scans = 0, localised = 0;
  std::size_t global_searches = 0, fixes = 0, ambiguous = 0, losses = 0;
  std::size_t candidates = 0;            ///< branch-and-bound candidates scored
  std::optional<std::size_t> first_fix;  ///< scan index (0-based, in the order given)
  double setup_seconds = 0.0;            ///< the map's matching grids
  double global_seconds = 0.0, track_seconds = 0.0;
};

/// \brief Check a user's initial pose against a map: finite, a yaw within ±kMaxAngle rad, the
/// position inside the map's extent. \throws std::invalid_argument saying which
void validateInitialPose(const Map2D& map, const Pose2D& pose);

/// \brief The localiser. Not thread-safe; the map is copied into its matching grids.
class Localizer2D {
 public:
  /// \throws std::invalid_argument naming a bad configuration value or an empty map;
  /// CapacityError when the matching grids do not fit in the memory budget
  Localizer2D(const Map2D& map, const Localizer2DConfig& config, const Pose2D& sensor_to_base = {});
  ~Localizer2D();
  Localizer2D(const Localizer2D&) = delete;
  Localizer2D& operator=(const Localizer2D&) = delete;

  /// \brief Start from a pose the user knows (map frame): the next scan is searched in the
  /// initial window around it instead of the whole map. \throws std::invalid_argument if not
  /// finite, a yaw beyond ±kMaxAngle, or a position outside the map
  void setInitialPose(const Pose2D& pose);

  /// \brief Localise the next scan, with the robot's raw odometry when known. Beams with a NaN
  /// range are skipped. \throws std::invalid_argument for a scan whose angles and ranges differ
  /// in count, or non-finite odometry
  Localization2D localize(const LaserScan& scan, const std::optional<Pose2D>& odometry = {});

  /// \brief The status of the last scan (NotFound before any).
  LocalizationStatus status() const;
  const Localizer2DStats& stats() const;
  const Localizer2DConfig& config() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace metricmap
