#include "metricmap/localization/localizer_3d.h"

#include <chrono>
#include <cmath>

#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/localization/global_search_3d.h"
#include "metricmap/localization/map_alignment_3d.h"
#include "metricmap/localization/map_places_3d.h"
#include "metricmap/localization/scan_ground_3d.h"
#include "metricmap/registration/voxel_downsample.h"
#include "metricmap/registration/voxel_hash_map.h"

namespace metricmap {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

bool rigid(const Eigen::Isometry3d& t) {
  return t.matrix().allFinite() &&
         (t.linear() * t.linear().transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-6 &&
         t.linear().determinant() > 0;
}

}  // namespace

struct Localizer3D::Impl {
  Localizer3DConfig config;
  Eigen::Isometry3d sensor_to_base;
  Eigen::AlignedBox3d bounds;
  std::vector<Eigen::Vector3f> map_points;
  VoxelHashMap hash;
  std::vector<MapPlace3D> places;
  PointToPointIcpWorkspace workspace;
  Localizer3DStats stats;
  LocalizationStatus status = LocalizationStatus::NotFound;
  // The track: the last two sensor poses (sensor -> map) and whether the robot is localised.
  bool tracking = false, have_velocity = false;
  Eigen::Isometry3d last = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d velocity = Eigen::Isometry3d::Identity();
  int weak_in_a_row = 0;
  std::optional<Eigen::Isometry3d> initial;  // sensor -> map

  Impl(const PointMap3D& map, const Localizer3DConfig& c, const Eigen::Isometry3d& s2b)
      : config(c),
        sensor_to_base(s2b),
        bounds(map.bounds),
        hash(c.map_voxel, c.map_points_per_voxel) {
    if (map.points.empty()) throw std::invalid_argument("the 3D map has no point");
    const auto start = std::chrono::steady_clock::now();
    std::vector<Eigen::Vector3d> points;
    points.reserve(map.points.size());
    for (const Eigen::Vector3f& p : map.points) points.push_back(p.cast<double>());
    const std::size_t voxels = voxelDownsample(points, c.map_voxel).size();
    checkMemory(voxels, 3 * sizeof(double) * std::size_t(c.map_points_per_voxel) + 32,
                "the 3D map's voxel hash (" + std::to_string(voxels) + " voxels)");
    // A spread of points in each voxel (not the first few the file lists).
    hash.add(voxelDownsample(points, c.map_voxel / 4));
    map_points = map.points;
    places = buildMapPlaces(map, c);
    stats.places = places.size();
    stats.setup_seconds = secondsSince(start);
  }

  std::vector<Eigen::Vector3d> prepare(const std::vector<Eigen::Vector3f>& scan) const {
    std::vector<Eigen::Vector3d> kept;
    kept.reserve(scan.size());
    for (const Eigen::Vector3f& p : scan) {
      if (!p.allFinite()) continue;
      const double r = p.cast<double>().norm();
      if (r >= config.min_range && r <= config.max_range) kept.push_back(p.cast<double>());
    }
    return voxelDownsample(kept, config.scan_voxel);
  }

  MapAlignmentParams trackParams(double coarse) const {
    return {coarse, config.track_fine_threshold, config.track_iterations, config.overlap_distance};
  }

  void startTrack(const Eigen::Isometry3d& pose) {
    tracking = true;
    have_velocity = false;
    last = pose;
    weak_in_a_row = 0;
  }

  Localization3D global(const std::vector<Eigen::Vector3d>& scan) {
    const auto start = std::chrono::steady_clock::now();
    Localization3D r;
    ++stats.global_searches;
    const GlobalSearch3D g = searchGlobally(scan, map_points, places, config);
    stats.candidates += g.candidates;
    r.status = g.status;
    r.score = g.score;
    r.margin = g.margin;
    if (g.status == LocalizationStatus::Fixed) {
      const MapAlignment3D a =
          alignToMap(scan, hash, g.pose, trackParams(config.track_fine_threshold), &workspace);
      startTrack(a.pose);
      r.pose = a.pose;
    } else if (g.status == LocalizationStatus::Ambiguous) {
      ++stats.ambiguous;
    }
    stats.global_seconds += secondsSince(start);
    return r;
  }

  Localization3D fromInitial(const std::vector<Eigen::Vector3d>& scan) {
    const auto start = std::chrono::steady_clock::now();
    Localization3D r;
    Eigen::Isometry3d guess = *initial;
    initial.reset();
    levelPrediction(scan, guess);
    searchYaw(scan, guess);
    const LoopVerification v = verifyGuess(scan, map_points, guess, config);
    r.score = v.structure_overlap;
    if (v.accepted) {
      const MapAlignment3D a =
          alignToMap(scan, hash, v.relation, trackParams(config.track_fine_threshold), &workspace);
      r.status = LocalizationStatus::Fixed;
      r.pose = a.pose;
      startTrack(a.pose);
    }
    stats.global_seconds += secondsSince(start);
    return r;
  }

  /// The prediction's roll and pitch replaced by the scan's ground (a platform that pitches
  /// and rolls as it moves is not predicted by its last motion); its heading kept.
  void levelPrediction(const std::vector<Eigen::Vector3d>& scan, Eigen::Isometry3d& pose) const {
    const ScanGround g =
        estimateScanGround(scan, config.ground_threshold, config.ground_max_tilt_deg);
    if (!g.found) return;
    const Eigen::Vector3d f = pose.linear().col(0), h = g.level.col(0);
    const double yaw = std::atan2(f.y(), f.x()) - std::atan2(h.y(), h.x());
    pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * g.level;
  }

  /// The heading within ±track_yaw_window_deg of the prediction (steps of track_yaw_step_deg)
  /// under which most of a subsample of the scan lies on the map: a turn the last motion did
  /// not predict is caught before the ICP, whose basin is narrower.
  void searchYaw(const std::vector<Eigen::Vector3d>& scan, Eigen::Isometry3d& pose) const {
    if (config.track_yaw_window_deg <= 0.0) return;
    std::vector<Eigen::Vector3d> sample;
    const std::size_t stride = std::max<std::size_t>(1, scan.size() / 400);
    for (std::size_t i = 0; i < scan.size(); i += stride) sample.push_back(scan[i]);
    const int steps = static_cast<int>(config.track_yaw_window_deg / config.track_yaw_step_deg);
    Eigen::Isometry3d best = pose;
    double best_overlap = -1.0;
    for (int k = -steps; k <= steps; ++k) {
      Eigen::Isometry3d p = pose;
      p.linear() = Eigen::AngleAxisd(k * config.track_yaw_step_deg * M_PI / 180.0,
                                     Eigen::Vector3d::UnitZ()) *
                   pose.linear();
      const double o = mapOverlap(sample, hash, p, config.track_coarse_threshold).overlap -
                       (k == 0 ? 0.0 : 1e-9 * std::abs(k));
      if (o > best_overlap) best_overlap = o, best = p;
    }
    pose = best;
  }

  Localization3D track(const std::vector<Eigen::Vector3d>& scan) {
    const auto start = std::chrono::steady_clock::now();
    Localization3D r;
    Eigen::Isometry3d predicted = have_velocity ? last * velocity : last;
    levelPrediction(scan, predicted);
    searchYaw(scan, predicted);
    const MapAlignment3D a =
        alignToMap(scan, hash, predicted, trackParams(config.track_coarse_threshold), &workspace);
    r.score = a.overlap;
    const double correction = (predicted.inverse() * a.pose).translation().norm();
    if (a.overlap >= config.track_min_overlap && correction <= config.track_max_correction) {
      r.status = LocalizationStatus::Tracked;
      r.pose = a.pose;
      velocity = last.inverse() * a.pose;
      have_velocity = true;
      last = a.pose;
      weak_in_a_row = 0;
    } else {
      r.status = LocalizationStatus::Weak;
      r.pose = a.pose;
      last = predicted;
      if (++weak_in_a_row >= config.lost_after_weak_scans) {
        r.status = LocalizationStatus::Lost;
        tracking = false;
        ++stats.losses;
      }
    }
    stats.track_seconds += secondsSince(start);
    return r;
  }
};

Localizer3D::Localizer3D(const PointMap3D& map, const Localizer3DConfig& config,
                         const Eigen::Isometry3d& sensor_to_base) {
  validateLocalizer3DConfig(config);
  if (!rigid(sensor_to_base)) throw std::invalid_argument("sensor_to_base is not a rigid motion");
  impl_ = std::make_unique<Impl>(map, config, sensor_to_base);
}

Localizer3D::~Localizer3D() = default;

void Localizer3D::setInitialPose(const Eigen::Isometry3d& pose) {
  if (!rigid(pose)) throw std::invalid_argument("the initial pose is not a finite rigid motion");
  Eigen::AlignedBox3d grown = impl_->bounds;
  const double r = impl_->config.descriptor.max_radius;
  grown.extend(impl_->bounds.max() + Eigen::Vector3d::Constant(r));
  grown.extend(impl_->bounds.min() - Eigen::Vector3d::Constant(r));
  if (!grown.contains(pose.translation()))
    throw std::invalid_argument("the initial pose lies outside the map (more than " +
                                std::to_string(r) + " m beyond its points)");
  impl_->initial = pose * impl_->sensor_to_base;
  impl_->tracking = false;
}

Localization3D Localizer3D::localize(const std::vector<Eigen::Vector3f>& scan) {
  Impl& m = *impl_;
  const std::vector<Eigen::Vector3d> points = m.prepare(scan);
  Localization3D r;
  if (m.initial)
    r = m.fromInitial(points);
  else if (m.tracking)
    r = m.track(points);
  else
    r = m.global(points);
  if (r.status == LocalizationStatus::Fixed) {
    ++m.stats.fixes;
    if (!m.stats.first_fix) m.stats.first_fix = m.stats.scans;
  }
  // Base -> map from sensor -> map.
  r.pose = r.pose * m.sensor_to_base.inverse();
  ++m.stats.scans;
  if (r.localised()) ++m.stats.localised;
  m.status = r.status;
  return r;
}

LocalizationStatus Localizer3D::status() const { return impl_->status; }
const Localizer3DStats& Localizer3D::stats() const { return impl_->stats; }
const Localizer3DConfig& Localizer3D::config() const { return impl_->config; }

}  // namespace metricmap
