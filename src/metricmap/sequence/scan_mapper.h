#pragma once
/// \file scan_mapper.h
/// \brief The mapping pipeline: scans in their sensor frame plus poses -> a registered global
/// cloud and a 2D hit map. One call per scan (`addScan`), one report per call.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include "metricmap/mapping/log_odds_grid_2d.h"
#include "metricmap/mapping/map_sinks.h"
#include "metricmap/mapping/occupancy_map_2d.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/registration/scan_registration.h"

namespace metricmap {

/// \brief What each scan is aligned to when registration is on.
enum class RegistrationTarget {
  Map,       ///< the registered scans so far, averaged in `target_voxel` cells
  Previous,  ///< the previous scan only
  First,     ///< the first scan only
};

/// \brief "map" | "previous" | "first". \throws std::invalid_argument
RegistrationTarget parseRegistrationTarget(const std::string& name);

/// \brief Registration of each scan (after the first) against a target, starting from the
/// pose the caller gives.
struct RegistrationConfig {
  bool enabled = false;
  RefineParams refine;                                  ///< ICP or GICP, distances, iterations
  RegistrationTarget target = RegistrationTarget::Map;  ///< what a scan is aligned to
  /// Which points of each scan register, and their cell (a sensor preset: KITTI's by default).
  RegistrationCloudParams cloud = RegistrationCloudParams::kittiHdl64();
  double target_voxel = 0.2;    ///< cell of the accumulated target with `Map` (m)
  std::size_t min_points = 20;  ///< fewer registration points in source or target: an error
};

/// \brief The 2D log-odds occupancy grid of a ScanMapper: the kept points whose height above
/// the sensor (along the world's `up`) lies in [band_min, band_max], projected onto the map
/// plane and cast from the sensor's projected position (LogOddsGrid2D). 2D laser scans lie at
/// height 0 and are all cast.
struct Occupancy2DConfig {
  LogOddsParams params;  ///< resolution, sensor model, max_range (OctoMap's defaults)
  double band_min = -0.5, band_max = 0.5;
};

/// \brief Parameters of ScanMapper. Ranges are in the sensor frame, heights in the world.
struct ScanMapperConfig {
  double min_range = 0.0;                                      ///< drop closer returns (m)
  double max_range = std::numeric_limits<double>::infinity();  ///< drop further returns (m)
  double voxel = 0.0;  ///< average each scan and the global cloud in cells of this size (0: off)
  double min_height = -std::numeric_limits<double>::infinity();  ///< map band, along `up`
  double max_height = std::numeric_limits<double>::infinity();
  Eigen::Vector3f up = Eigen::Vector3f(0, -1, 0);  ///< the world's up axis (KITTI camera: -y)
  MapPlane plane = MapPlane::XZ;                   ///< projection plane of the 2D map
  double map_resolution = 0.1;                     ///< 2D map cell (m)
  std::uint32_t min_hits = 1;                      ///< hits that make a map cell occupied
  bool keep_global_cloud = true;                   ///< accumulate the registered scans
  RegistrationConfig registration;
  /// Poses from the scans themselves (LidarOdometry) for addScan(scan) without a pose.
  bool odometry = false;
  LidarOdometryConfig odometry_config;
  /// World pose of the first scan's sensor for odometry poses (KITTI camera world: Tr).
  Eigen::Isometry3d odometry_origin = Eigen::Isometry3d::Identity();
  /// Probabilistic 3D occupancy (LogOddsMap, OctoMap's sensor model): every point of each scan,
  /// as given (no range band), cast from the sensor's position with the pose used. Off when
  /// empty.
  std::optional<LogOddsParams> occupancy;
  /// 2D log-odds occupancy grid in the map plane. Off when empty.
  std::optional<Occupancy2DConfig> occupancy_2d;
};

/// \brief \throws std::invalid_argument naming the first bad parameter
void validateScanMapperConfig(const ScanMapperConfig& config);

/// \brief What `addScan` did with one scan.
struct FrameReport {
  std::size_t index = 0;            ///< 0 for the first scan added
  std::uint64_t points_read = 0;    ///< points of the scan as given
  std::uint64_t points_kept = 0;    ///< after the range band (and the voxel, when on)
  std::uint64_t points_mapped = 0;  ///< within the height band, counted in the 2D map
  Eigen::Isometry3d pose_given = Eigen::Isometry3d::Identity();  ///< sensor -> world, as given
  Eigen::Isometry3d pose_used = Eigen::Isometry3d::Identity();   ///< after registration
  bool registered = false;                                       ///< registration ran for this scan
  bool converged = false;  ///< PCL's hasConverged of the last stage
  double fitness = 0.0;    ///< PCL's fitness score of the last stage
  double seconds_register = 0.0, seconds_transform = 0.0, seconds_map = 0.0;
  double seconds_occupancy = 0.0;     ///< ray casting into the log-odds map (when on)
  double seconds_occupancy_2d = 0.0;  ///< beams cast into the 2D grid (when on)
  std::uint64_t beams_2d = 0;         ///< beams cast into the 2D grid
};

/// \brief Per-frame and RMS translation error of a trajectory against a reference.
struct TrajectoryError {
  std::vector<PoseError> given;  ///< reference vs the poses given to addScan
  std::vector<PoseError> used;   ///< reference vs the poses used (registered)
  double ate_given = 0.0;        ///< RMS of `given` translations (m)
  double ate_used = 0.0;         ///< RMS of `used` translations (m)
};

/// \brief Scans + poses -> the maps of its sinks (mapping/map_sinks.h): the 2D hit map, the
/// global cloud, and as configured the 3D log-odds map and the 2D log-odds grid.
///
/// Each scan's pose comes from the caller or from the odometry, optionally refined by
/// registration against a target (the estimators); the scan is cut to the range band in its
/// own frame, moved to the world, optionally averaged in `voxel` cells, and handed to every
/// sink.
/// \note Thread safety: one instance per thread.
class ScanMapper {
 public:
  using Cloud = pcl::PointCloud<pcl::PointXYZ>;

  /// \throws std::invalid_argument for a bad configuration
  explicit ScanMapper(const ScanMapperConfig& config);

  /// \brief Add one scan (sensor frame) with its sensor -> world pose.
  /// \throws InputError when registration is on and the scan or target has too few points
  FrameReport addScan(const Cloud& scan_in_sensor, const Eigen::Isometry3d& pose);

  /// \brief Add one scan (sensor frame) whose pose comes from LidarOdometry: the odometry's
  /// pose (sensor -> first sensor) moved by `odometry_origin`; registration, when on, refines it.
  /// \throws std::logic_error unless `odometry` is on; InputError for a scan with no usable point
  FrameReport addScan(const Cloud& scan_in_sensor);

  /// \brief The odometry's result for the last scan added with addScan(scan).
  const OdometryResult& lastOdometry() const { return last_odometry_; }

  /// \brief The log-odds map so far; null unless `occupancy` is configured.
  const LogOddsMap* occupancy() const { return log_odds_ ? &log_odds_->map() : nullptr; }
  /// \brief The 2D log-odds grid so far; null unless `occupancy_2d` is configured.
  const LogOddsGrid2D* occupancy2D() const { return grid_2d_ ? &grid_2d_->grid() : nullptr; }

  /// \brief The 2D hit map so far.
  const OccupancyMap2D& map() const { return hit_map_.map(); }
  /// \brief Cells of the map with at least `min_hits` hits.
  std::size_t occupiedCells() const;
  /// \brief The registered scans in the world, averaged in `voxel` cells when it is > 0.
  Cloud globalCloud() const;
  /// \brief The current registration target (world frame); empty without registration.
  const Cloud& registrationTarget() const { return *target_; }
  /// \brief Sensor -> world poses used, one per scan added.
  const std::vector<Eigen::Isometry3d>& poses() const { return used_; }
  /// \brief Sensor -> world poses as given, one per scan added.
  const std::vector<Eigen::Isometry3d>& givenPoses() const { return given_; }
  /// \brief Error of the given and the used poses against `reference` (one per scan added).
  /// \throws std::invalid_argument when the sizes differ
  TrajectoryError trajectoryError(const std::vector<Eigen::Isometry3d>& reference) const;
  const ScanMapperConfig& config() const { return config_; }

 private:
  void updateTarget(const Cloud& kept_in_sensor, const Eigen::Isometry3d& pose);
  void registerScan(const Cloud& kept, FrameReport& report);
  void insertIntoSinks(const Cloud& scan_in_sensor, const Cloud& world, FrameReport& report);

  ScanMapperConfig config_;
  // The sinks (the hit map and the global cloud always; the log-odds maps as configured).
  HitMapSink hit_map_;
  GlobalCloudSink global_;
  std::unique_ptr<LogOddsMapSink> log_odds_;
  std::unique_ptr<LogOddsGrid2DSink> grid_2d_;
  // The estimators: registration's target, the odometry.
  Cloud::Ptr target_;
  std::unique_ptr<LidarOdometry> odometry_;
  OdometryResult last_odometry_;
  std::vector<Eigen::Isometry3d> given_, used_;
};

/// \brief The points of `scan` whose distance from the origin lies in [min_range, max_range].
pcl::PointCloud<pcl::PointXYZ> rangeBand(const pcl::PointCloud<pcl::PointXYZ>& scan,
                                         double min_range, double max_range);

}  // namespace metricmap
