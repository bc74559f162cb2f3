#include "metricmap/sequence/scan_mapper.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <pcl/common/transforms.h>

#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

std::string str(double v) { return formatNumber(v); }

}  // namespace

RegistrationTarget parseRegistrationTarget(const std::string& name) {
  if (name == "map") return RegistrationTarget::Map;
  if (name == "previous") return RegistrationTarget::Previous;
  if (name == "first") return RegistrationTarget::First;
  throw std::invalid_argument("registration target must be map, previous or first, got '" + name +
                              "'");
}

void validateScanMapperConfig(const ScanMapperConfig& c) {
  require(std::isfinite(c.min_range) && c.min_range >= 0.0,
          "min range must be a finite number >= 0, got " + str(c.min_range));
  require(!std::isnan(c.max_range) && c.max_range > 0.0,
          "max range must be a number > 0, got " + str(c.max_range));
  require(c.min_range <= c.max_range,
          "min range " + str(c.min_range) + " exceeds max range " + str(c.max_range));
  require(std::isfinite(c.voxel) && c.voxel >= 0.0,
          "voxel must be a finite number >= 0 (0: off), got " + str(c.voxel));
  // The clouds are float: 1e39 would be an infinite voxel, 1e-300 a zero one.
  require(!beyondFloatRange(c.voxel) && !belowFloatRange(c.voxel),
          "voxel " + str(c.voxel) + " is outside the single-precision range");
  require(!std::isnan(c.min_height) && !std::isnan(c.max_height),
          "height band bounds must not be NaN");
  require(c.min_height <= c.max_height,
          "min height " + str(c.min_height) + " exceeds max height " + str(c.max_height));
  require(c.up.allFinite() && c.up.norm() > 0.0f, "the up axis must be a finite non-zero vector");
  require(std::isfinite(c.map_resolution) && c.map_resolution > 0.0,
          "map resolution must be a finite number > 0, got " + str(c.map_resolution));
  const RegistrationConfig& r = c.registration;
  validateRegistrationCloudParams(r.cloud);
  require(std::isfinite(r.target_voxel) && r.target_voxel > 0.0,
          "registration target voxel must be a finite number > 0, got " + str(r.target_voxel));
  require(std::isfinite(r.refine.max_correspondence) && r.refine.max_correspondence > 0.0,
          "max correspondence distance must be a finite number > 0, got " +
              str(r.refine.max_correspondence));
  require(r.refine.max_iterations > 0, "registration needs at least one iteration");
  require(r.min_points >= 1, "registration needs a minimum of at least one point");
  if (c.occupancy_2d) {
    const Occupancy2DConfig& o = *c.occupancy_2d;
    require(!std::isnan(o.band_min) && !std::isnan(o.band_max) && o.band_min <= o.band_max,
            "2D occupancy band must be MIN,MAX with MIN <= MAX, got " + str(o.band_min) + "," +
                str(o.band_max));
    validateLogOddsParams(o.params);
  }
  if (c.occupancy) validateLogOddsParams(*c.occupancy);
}

pcl::PointCloud<pcl::PointXYZ> rangeBand(const pcl::PointCloud<pcl::PointXYZ>& scan,
                                         double min_range, double max_range) {
  pcl::PointCloud<pcl::PointXYZ> out;
  out.reserve(scan.size());
  for (const auto& p : scan) {
    const double r = p.getVector3fMap().norm();
    if (r >= min_range && r <= max_range) out.push_back(p);
  }
  out.width = static_cast<std::uint32_t>(out.size());
  out.height = 1;
  return out;
}

ScanMapper::ScanMapper(const ScanMapperConfig& config)
    : config_(config),
      hit_map_((validateScanMapperConfig(config), config.map_resolution), config.plane, config.up,
               config.min_height, config.max_height),
      global_(config.voxel),
      target_(std::make_shared<Cloud>()) {
  if (config.odometry) odometry_ = std::make_unique<LidarOdometry>(config.odometry_config);
  if (config.occupancy) log_odds_ = std::make_unique<LogOddsMapSink>(*config.occupancy);
  if (config.occupancy_2d) {
    const Occupancy2DConfig& o = *config.occupancy_2d;
    grid_2d_ = std::make_unique<LogOddsGrid2DSink>(o.params, config.plane, config.up, o.band_min,
                                                   o.band_max);
  }
}

FrameReport ScanMapper::addScan(const Cloud& scan_in_sensor) {
  if (!odometry_) throw std::logic_error("ScanMapper::addScan(scan) needs `odometry` on");
  const auto t = std::chrono::steady_clock::now();
  last_odometry_ =
      odometry_->registerFrame(scan_in_sensor, {}, "scan " + std::to_string(used_.size()));
  const double odometry_s = secondsSince(t);
  FrameReport r = addScan(scan_in_sensor, config_.odometry_origin * last_odometry_.pose);
  r.seconds_register += odometry_s;
  return r;
}

FrameReport ScanMapper::addScan(const Cloud& scan_in_sensor, const Eigen::Isometry3d& pose) {
  FrameReport report;
  report.index = used_.size();
  report.points_read = scan_in_sensor.size();
  report.pose_given = pose;
  report.pose_used = pose;

  auto t = std::chrono::steady_clock::now();
  Cloud kept = rangeBand(scan_in_sensor, config_.min_range, config_.max_range);
  report.seconds_transform += secondsSince(t);
  if (config_.registration.enabled && report.index > 0) registerScan(kept, report);

  t = std::chrono::steady_clock::now();
  if (config_.registration.enabled) updateTarget(kept, report.pose_used);
  Cloud world;
  pcl::transformPointCloud(kept, world, report.pose_used.matrix().cast<float>());
  report.seconds_transform += secondsSince(t);
  insertIntoSinks(scan_in_sensor, world, report);
  given_.push_back(pose);
  used_.push_back(report.pose_used);
  return report;
}

void ScanMapper::registerScan(const Cloud& kept, FrameReport& report) {
  const RegistrationConfig& reg = config_.registration;
  const auto t = std::chrono::steady_clock::now();
  const Cloud::Ptr source = registrationCloud(kept, reg.cloud);
  if (source->size() < reg.min_points || target_->size() < reg.min_points) {
    throw InputError("scan " + std::to_string(report.index) + ": registration needs at least " +
                     std::to_string(reg.min_points) + " points in the scan and the target (" +
                     std::to_string(source->size()) + " and " + std::to_string(target_->size()) +
                     " within 3-40 m above the ground); widen the range band");
  }
  const RefineResult r = refineScanPose(source, target_, report.pose_given, reg.refine);
  report.pose_used = r.scan_to_world;
  report.registered = true;
  report.converged = r.converged;
  report.fitness = r.fitness;
  report.seconds_register = secondsSince(t);
}

void ScanMapper::insertIntoSinks(const Cloud& scan_in_sensor, const Cloud& world,
                                 FrameReport& report) {
  auto t = std::chrono::steady_clock::now();
  const Cloud averaged = config_.voxel > 0.0 ? voxelAverage(world, config_.voxel) : Cloud();
  const SinkScan scan{scan_in_sensor, world, config_.voxel > 0.0 ? averaged : world,
                      report.pose_used};
  report.points_kept = scan.averaged.size();
  report.seconds_transform += secondsSince(t);
  if (grid_2d_) {
    t = std::chrono::steady_clock::now();
    report.beams_2d = grid_2d_->insert(scan);
    report.seconds_occupancy_2d = secondsSince(t);
  }
  t = std::chrono::steady_clock::now();
  report.points_mapped = hit_map_.insert(scan);
  report.seconds_map = secondsSince(t);
  if (log_odds_) {
    t = std::chrono::steady_clock::now();
    log_odds_->insert(scan);
    report.seconds_occupancy = secondsSince(t);
  }
  if (config_.keep_global_cloud) global_.insert(scan);
}

void ScanMapper::updateTarget(const Cloud& kept_in_sensor, const Eigen::Isometry3d& pose) {
  const RegistrationConfig& reg = config_.registration;
  if (reg.target == RegistrationTarget::First && !used_.empty()) return;
  Cloud structure;
  pcl::transformPointCloud(*registrationCloud(kept_in_sensor, reg.cloud), structure,
                           pose.matrix().cast<float>());
  if (reg.target == RegistrationTarget::Map) {
    *target_ += structure;
    *target_ = voxelAverage(*target_, reg.target_voxel);
  } else {
    *target_ = std::move(structure);
  }
}

std::size_t ScanMapper::occupiedCells() const { return map().occupied(config_.min_hits); }

ScanMapper::Cloud ScanMapper::globalCloud() const { return global_.cloud(); }

TrajectoryError ScanMapper::trajectoryError(const std::vector<Eigen::Isometry3d>& reference) const {
  if (reference.size() != used_.size()) {
    throw std::invalid_argument("trajectory error: " + std::to_string(reference.size()) +
                                " reference poses for " + std::to_string(used_.size()) + " scans");
  }
  TrajectoryError e;
  double sq_given = 0.0, sq_used = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    e.given.push_back(poseError(reference[i], given_[i]));
    e.used.push_back(poseError(reference[i], used_[i]));
    sq_given += e.given.back().translation * e.given.back().translation;
    sq_used += e.used.back().translation * e.used.back().translation;
  }
  if (!reference.empty()) {
    e.ate_given = std::sqrt(sq_given / static_cast<double>(reference.size()));
    e.ate_used = std::sqrt(sq_used / static_cast<double>(reference.size()));
  }
  return e;
}

}  // namespace metricmap
