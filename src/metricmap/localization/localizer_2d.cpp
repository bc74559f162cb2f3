#include "metricmap/localization/localizer_2d.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/rigid_transform.h"
#include "metricmap/localization/map_matcher_2d.h"
#include "metricmap/localization/scan_points_2d.h"
#include "metricmap/posegraph/pose_graph.h"
#include "metricmap/slam/scan_matcher_2d.h"

namespace metricmap {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

bool finite(const Pose2D& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta);
}

}  // namespace

namespace {

/// The initial pose's yaw within ±kMaxAngle and its position inside the map (a grid of
/// extent_x × extent_y m whose lower-left corner is at `origin`).
void checkInitialPose(const Pose2D& origin, double extent_x, double extent_y, const Pose2D& pose) {
  if (!finite(pose)) throw std::invalid_argument("the initial pose is not finite");
  if (std::fabs(pose.theta) > kMaxAngle) {
    std::ostringstream msg;
    msg << "the initial pose's yaw " << pose.theta << " rad is beyond +-" << kMaxAngle << " rad";
    throw std::invalid_argument(msg.str());
  }
  const Pose2D in_grid = compose(inverse(origin), pose);
  if (!(in_grid.x >= 0.0 && in_grid.y >= 0.0 && in_grid.x <= extent_x && in_grid.y <= extent_y)) {
    std::ostringstream msg;
    msg << "the initial pose (" << pose.x << ", " << pose.y << ") is outside the map";
    if (origin.theta == 0.0)
      msg << " (x " << origin.x << " to " << origin.x + extent_x << ", y " << origin.y << " to "
          << origin.y + extent_y << " m)";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

void validateInitialPose(const Map2D& map, const Pose2D& pose) {
  checkInitialPose(map.origin, map.width * map.resolution, map.height * map.resolution, pose);
}

struct Localizer2D::Impl {
  Localizer2DConfig config;
  Pose2D sensor, origin, to_grid;         ///< to_grid: grid <- world
  double extent_x = 0.0, extent_y = 0.0;  ///< the map's size (m), grid frame
  MapMatcher2D matcher;
  bool tracking = false;
  Pose2D pose;                    ///< last pose, grid frame
  std::optional<Pose2D> initial;  ///< grid frame
  std::optional<Pose2D> last_odometry;
  Pose2D last_motion;
  std::size_t weak_run = 0, unlocalised_run = 0;
  std::optional<Pose2D> searched_odometry;  ///< the odometry at the last global search

  /// While not localised: search this scan? The first one, then once the odometry has moved
  /// far enough since the last search (the same view gives the same answer), or every
  /// global_every_n_scans scans.
  bool searchDue(const std::optional<Pose2D>& odometry) const {
    if (initial || unlocalised_run % config.global_every_n_scans == 0) return true;
    if (!odometry || !searched_odometry) return false;
    const Pose2D moved = compose(inverse(*searched_odometry), *odometry);
    return std::hypot(moved.x, moved.y) >= config.global_min_motion ||
           std::fabs(moved.theta) >= config.global_min_turn_deg * kDeg;
  }
  LocalizationStatus status = LocalizationStatus::NotFound;
  Localizer2DStats stats;

  Impl(const Map2D& map, const Localizer2DConfig& c, const Pose2D& s)
      : config(c),
        sensor(s),
        origin(map.origin),
        to_grid(inverse(map.origin)),
        extent_x(map.width * map.resolution),
        extent_y(map.height * map.resolution),
        matcher(map, c.occupied_probability, c.free_probability, c.branch_and_bound_depth,
                c.global_coarsening) {}

  ScanMatch2D refine(const std::vector<Eigen::Vector2f>& points, const Pose2D& from) const {
    return refinePose(matcher.grid(), points, from, from, config.translation_weight,
                      config.rotation_weight, config.refine_iterations);
  }

  /// A pose from the search's grid on the map's: a correlative search over one coarse cell
  /// and one coarse angular step, then Gauss-Newton; its score on every point.
  ScanMatch2D polish(const std::vector<Eigen::Vector2f>& points,
                     const std::vector<Eigen::Vector2f>& coarse, const Pose2D& from) const {
    Pose2D start = from;
    const double res = matcher.resolution(), search_res = matcher.searchResolution();
    if (search_res > res)
      start =
          correlativeSearch(matcher.grid(), points, from, search_res,
                            angularSearchStep(search_res, coarse), angularSearchStep(res, points))
              .pose;
    return refine(points, start);
  }

  /// The branch-and-bound in a window; the best pose and its search score.
  std::optional<ScanMatch2D> search(const std::vector<Eigen::Vector2f>& coarse,
                                    const Pose2D& centre, double linear, double angular,
                                    double floor, const SearchExclusion2D* exclude) {
    const BranchAndBoundMatcher2D& bnb = matcher.branchAndBound();
    const std::optional<ScanMatch2D> m =
        bnb.match(coarse, centre, linear, angular, std::max(floor, 1e-3), exclude);
    stats.candidates += bnb.lastCandidates();
    return m;
  }

  /// Global search over the whole map (or the initial window): Fixed, Ambiguous or NotFound.
  Localization2D globalSearch(const std::vector<Eigen::Vector2f>& points,
                              const std::optional<Pose2D>& around) {
    const Localizer2DConfig& c = config;
    const auto t0 = Clock::now();
    stats.global_searches++;
    Localization2D r;
    r.status = LocalizationStatus::NotFound;
    const std::vector<Eigen::Vector2f> coarse = spreadSubset(points, c.global_search_points);
    const double res = matcher.resolution();
    const Pose2D centre = around ? *around : Pose2D{matcher.sizeX() / 2, matcher.sizeY() / 2, 0.0};
    const double linear =
        around ? c.initial_linear_window : std::max(matcher.sizeX(), matcher.sizeY()) / 2 + res;
    const double angular = around ? c.initial_angular_window_deg * kDeg : kPi;
    // The search's score is on a subset of the points: its floor is below the refined one's.
    const double floor = c.global_min_score - 0.1;
    const std::optional<ScanMatch2D> best =
        coarse.empty() ? std::nullopt : search(coarse, centre, linear, angular, floor, nullptr);
    if (best) {
      ScanMatch2D refined = polish(points, coarse, best->pose);
      std::optional<ScanMatch2D> other;
      if (!around && refined.score >= c.global_min_score) {
        // The best distinct pose: the same search with the best's neighbourhood excluded, down
        // to a floor below the best (what scores less there cannot come within the margin once
        // refined), then refined like the best. The coarse grid can rank two places the other
        // way round: the better refined one is the fix, the margin is between refined scores.
        const SearchExclusion2D exclude{best->pose, c.global_distinct_distance,
                                        c.global_distinct_angle_deg * kDeg};
        const double runner_floor = std::max(floor, best->score - 3 * c.global_min_margin);
        if (const auto second = search(coarse, centre, linear, angular, runner_floor, &exclude)) {
          other = polish(points, coarse, second->pose);
          const bool distinct =
              std::hypot(other->pose.x - refined.pose.x, other->pose.y - refined.pose.y) >
                  c.global_distinct_distance ||
              std::fabs(std::remainder(other->pose.theta - refined.pose.theta, 2 * kPi)) >
                  c.global_distinct_angle_deg * kDeg;
          if (!distinct) other.reset();
          if (other && other->score > refined.score) std::swap(*other, refined);
        }
      }
      r.pose = refined.pose;
      r.score = refined.score;
      r.margin = other ? refined.score - other->score : 3 * c.global_min_margin;
      r.crossing = matcher.crossing(
          coarse, Eigen::Vector2f(static_cast<float>(sensor.x), static_cast<float>(sensor.y)),
          refined.pose, c.global_crossing_clearance);
      if (refined.score >= c.global_min_score && r.crossing <= c.global_max_crossing)
        r.status = around || r.margin >= c.global_min_margin ? LocalizationStatus::Fixed
                                                             : LocalizationStatus::Ambiguous;
    }
    if (r.status == LocalizationStatus::Ambiguous) stats.ambiguous++;
    stats.global_seconds += since(t0);
    return r;
  }

  Localization2D track(const std::vector<Eigen::Vector2f>& points, const Pose2D& predicted) {
    const Localizer2DConfig& c = config;
    const auto t0 = Clock::now();
    Localization2D r;
    r.pose = predicted;
    if (!points.empty()) {
      const double turned = std::fabs(std::remainder(predicted.theta - pose.theta, 2 * kPi));
      const double window =
          c.track_angular_window_deg * kDeg + c.track_angular_window_per_turn * turned;
      const ScanMatch2D coarse =
          correlativeSearch(matcher.grid(), points, predicted, c.track_linear_window,
                            std::min(window, kPi), angularSearchStep(matcher.resolution(), points));
      const ScanMatch2D m = refine(points, coarse.pose);
      r.pose = m.pose;
      r.score = m.score;
    }
    if (r.score >= c.track_min_score) {
      r.status = LocalizationStatus::Tracked;
      weak_run = 0;
    } else if (++weak_run >= c.lost_after_weak_scans) {
      r.status = LocalizationStatus::Lost;
    } else {
      r.status = LocalizationStatus::Weak;
    }
    stats.track_seconds += since(t0);
    return r;
  }
};

Localizer2D::Localizer2D(const Map2D& map, const Localizer2DConfig& config,
                         const Pose2D& sensor_to_base) {
  validateLocalizer2DConfig(config);
  if (!finite(sensor_to_base))
    throw std::invalid_argument("the sensor's pose on the robot is not finite");
  const auto t0 = Clock::now();
  impl_ = std::make_unique<Impl>(map, config, sensor_to_base);
  impl_->stats.setup_seconds = since(t0);
}

Localizer2D::~Localizer2D() = default;

void Localizer2D::setInitialPose(const Pose2D& pose) {
  Impl& d = *impl_;
  checkInitialPose(d.origin, d.extent_x, d.extent_y, pose);
  const Pose2D in_grid = compose(d.to_grid, pose);
  d.initial = in_grid;
  d.tracking = false;
  d.unlocalised_run = 0;
}

Localization2D Localizer2D::localize(const LaserScan& scan, const std::optional<Pose2D>& odometry) {
  Impl& d = *impl_;
  const Localizer2DConfig& c = d.config;
  if (scan.angles.size() != scan.ranges.size())
    throw std::invalid_argument("scan has " + std::to_string(scan.angles.size()) + " angles but " +
                                std::to_string(scan.ranges.size()) + " ranges");
  if (odometry && !finite(*odometry)) throw std::invalid_argument("odometry pose is not finite");
  const auto t0 = Clock::now();
  const std::vector<Eigen::Vector2f> points =
      scanPoints2D(scan, d.sensor, c.min_range, c.max_range, c.voxel_filter);
  d.stats.track_seconds += since(t0);
  Localization2D r;
  if (d.tracking) {
    const Pose2D step =
        odometry && d.last_odometry ? compose(inverse(*d.last_odometry), *odometry) : d.last_motion;
    const Pose2D previous = d.pose;
    r = d.track(points, compose(previous, step));
    d.last_motion = compose(inverse(previous), r.pose);
    d.pose = r.pose;
    if (r.status == LocalizationStatus::Lost) {
      d.tracking = false;
      d.unlocalised_run = 0;
      d.searched_odometry.reset();
      d.stats.losses++;
    }
  } else if (d.searchDue(odometry)) {
    r = d.globalSearch(points, d.initial);
    d.initial.reset();
    d.searched_odometry = odometry;
    d.unlocalised_run = 1;
    if (r.status == LocalizationStatus::Fixed) {
      d.tracking = true;
      d.pose = r.pose;
      d.last_motion = {};
      d.weak_run = 0;
      d.stats.fixes++;
      if (!d.stats.first_fix) d.stats.first_fix = d.stats.scans;
    }
  } else {
    r.status = LocalizationStatus::Waiting;
    d.unlocalised_run++;
  }
  if (odometry) d.last_odometry = odometry;
  r.pose = compose(d.origin, r.pose);
  d.status = r.status;
  d.stats.scans++;
  if (r.localised()) d.stats.localised++;
  return r;
}

LocalizationStatus Localizer2D::status() const { return impl_->status; }
const Localizer2DStats& Localizer2D::stats() const { return impl_->stats; }
const Localizer2DConfig& Localizer2D::config() const { return impl_->config; }

}  // namespace metricmap
