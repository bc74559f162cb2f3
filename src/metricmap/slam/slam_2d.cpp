#include "metricmap/slam/slam_2d.h"

#include "metricmap/slam/slam_2d_parameters.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <stdexcept>
#include <unordered_set>

#include "metricmap/posegraph/optimize.h"
#include "metricmap/slam/branch_and_bound_2d.h"
#include "metricmap/slam/match_grid.h"
#include "metricmap/slam/scan_matcher_2d.h"

namespace metricmap {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Eigen::Vector2f apply(const Pose2D& pose, const Eigen::Vector2f& p) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return {static_cast<float>(pose.x + c * p.x() - s * p.y()),
          static_cast<float>(pose.y + s * p.x() + c * p.y())};
}

/// One point per square of `edge` (the first of each), in scan order.
std::vector<Eigen::Vector2f> voxelFilter(const std::vector<Eigen::Vector2f>& points, double edge) {
  std::vector<Eigen::Vector2f> kept;
  std::unordered_set<std::int64_t> seen;
  seen.reserve(points.size() * 2);
  for (const Eigen::Vector2f& p : points) {
    const auto i = static_cast<std::int64_t>(std::floor(p.x() / edge));
    const auto j = static_cast<std::int64_t>(std::floor(p.y() / edge));
    if (seen.insert(i * 73856093 ^ j * 19349663).second) kept.push_back(p);
  }
  return kept;
}

PoseGraph2D::Information informationOf(double sigma_m, double sigma_deg) {
  PoseGraph2D::Information info = PoseGraph2D::Information::Zero();
  const double sr = sigma_deg * kPi / 180.0;
  info(0, 0) = info(1, 1) = 1.0 / (sigma_m * sigma_m);
  info(2, 2) = 1.0 / (sr * sr);
  return info;
}

LogOddsParams submapParams(const Slam2DConfig& c) {
  LogOddsParams p;
  p.resolution = c.resolution;
  p.prob_hit = c.prob_hit;
  p.prob_miss = c.prob_miss;
  p.max_range = c.max_range;
  return p;
}

}  // namespace

void validateSlam2DConfig(const Slam2DConfig& c) {
  checkSlam2DParameterRanges(c);  // every field against its declaration (slam_2d_parameters)
  if (!(c.max_range > c.min_range)) {
    throw std::invalid_argument("max_range must be greater than min_range");
  }
  try {
    validateLogOddsParams(c.map);
  } catch (const std::invalid_argument& e) {  // the map's parameters are map_* by name
    throw std::invalid_argument(std::string("map_") + e.what());
  }
}

struct Slam2D::Impl {
  enum class Search { Near, Wide, NearAndWide, EndWide, EndNear };

  struct Submap {
    std::unique_ptr<LogOddsGrid2D> grid;
    std::size_t anchor = 0;  ///< first node
    std::size_t last_node = 0;
    std::size_t nodes = 0;
    Eigen::Vector2d centre_local = Eigen::Vector2d::Zero();  ///< mean node position, local
    std::unique_ptr<BranchAndBoundMatcher2D> matcher;        ///< when finished
  };
  struct Node {
    std::size_t scan = 0;
    Pose2D local;
    std::vector<Eigen::Vector2f> ends;    ///< base frame, every beam with a range
    std::vector<Eigen::Vector2f> points;  ///< base frame, filtered, for matching
  };

  Slam2DConfig config;
  Pose2D sensor;
  ProbabilityTable table;
  PoseGraph2D graph;
  PoseGraph2D::Information information, loop_information;
  std::vector<Node> nodes;
  std::uint64_t node_bytes = 0;  ///< the nodes' beams and points
  std::vector<Submap> submaps;
  std::deque<std::size_t> active;       ///< submap indices, oldest first (at most 2)
  std::vector<Pose2D> local;            ///< per scan
  std::vector<std::size_t> scan_node;   ///< per scan: the last node at or before it
  std::vector<std::size_t> node_scans;  ///< per node
  std::vector<LoopClosure2D> loops;
  std::optional<Pose2D> last_odometry;  ///< the last odometry reading that changed
  Pose2D odometry_origin;          ///< the estimated pose at the scan where that reading first came
  Pose2D last_motion;              ///< estimated motion between the last two scans
  bool odometry_repeated = false;  ///< a scan after that one came with the same reading
  double last_node_stamp = 0.0;
  std::size_t last_loop_node = 0;
  std::size_t nodes_at_last_optimization = 0;
  bool loops_since_optimization = false;
  Pose2D correction;  ///< global <- local, from the last optimisation
  std::unique_ptr<LogOddsGrid2D> map;
  bool finished = false;
  bool final_round = false;
  Slam2DStats stats;

  Impl(const Slam2DConfig& c, const Pose2D& s) : config(c), sensor(s), table(submapParams(c)) {
    information = informationOf(c.edge_translation_sigma, c.edge_rotation_sigma_deg);
    loop_information = informationOf(c.loop_translation_sigma, c.loop_rotation_sigma_deg);
  }

  Pose2D globalOf(std::size_t node) const { return graph.vertex(node).pose; }

  /// The share of `points` at `pose` that fall on observed cells of `grid`.
  static double overlap(const LogOddsGrid2D& grid, const std::vector<Eigen::Vector2f>& points,
                        const Pose2D& pose) {
    if (points.empty()) return 0.0;
    const double inv = 1.0 / grid.params().resolution;
    std::size_t known = 0;
    for (const Eigen::Vector2f& p : points) {
      const Eigen::Vector2f w = apply(pose, p);
      const auto i = static_cast<std::int64_t>(std::floor(w.x() * inv));
      const auto j = static_cast<std::int64_t>(std::floor(w.y() * inv));
      if (grid.state(i, j) != CellState::Unknown) ++known;
    }
    return static_cast<double>(known) / static_cast<double>(points.size());
  }

  /// The graph without the loop edges whose chi² exceeds loop_max_chi2.
  void removeLoopOutliers() {
    std::vector<bool> drop(graph.edgeCount(), false);
    bool any = false;
    for (const LoopClosure2D& l : loops)
      if (graph.edgeChi2(l.edge) > config.loop_max_chi2) drop[l.edge] = any = true;
    if (!any) return;
    PoseGraph2D kept;
    for (const auto& v : graph.vertices()) kept.addVertex(v.id, v.pose);
    std::vector<std::size_t> new_index(graph.edgeCount());
    for (std::size_t e = 0; e < graph.edgeCount(); ++e) {
      if (drop[e]) continue;
      const auto& edge = graph.edge(e);
      new_index[e] =
          kept.addEdge(edge.from, edge.to, edge.measurement, edge.information, edge.loop);
    }
    std::vector<LoopClosure2D> still;
    for (LoopClosure2D l : loops) {
      if (drop[l.edge]) {
        stats.loops_rejected++;
        continue;
      }
      l.edge = new_index[l.edge];
      still.push_back(l);
    }
    loops.swap(still);
    graph = std::move(kept);
  }

  void optimizeGraph(int iterations) {
    if (graph.edgeCount() == 0) return;  // one node: nothing to optimise
    const auto t0 = Clock::now();
    PoseGraphOptimizeOptions o;
    o.max_iterations = iterations;
    o.loop_loss = RobustLoss::Huber;
    o.loss_scale = std::sqrt(config.loop_max_chi2);
    // Each optimisation during the run starts from the last one's poses, so a short one costs
    // nothing lasting: Ceres' damped start and a 1e-6 gain per step keep them short. The final
    // one runs to the optimum (the options' defaults).
    if (!final_round) {
      o.initial_trust_region_radius = 1e4;
      o.function_tolerance = 1e-6;
    }
    PoseGraphOptimizeResult r = optimize(graph, o);
    // At the end, until no loop edge exceeds loop_max_chi2: removing the worst matches moves
    // the poses, and an edge that was just below the limit may no longer be.
    while (final_round) {
      const std::size_t before = loops.size();
      removeLoopOutliers();
      if (loops.size() == before) break;
      r = optimize(graph, o);
    }
    stats.optimizations++;
    stats.final_chi2_initial = r.initial_chi2;
    stats.final_chi2 = r.final_chi2;
    stats.final_iterations = r.iterations;
    const std::size_t last = nodes.size() - 1;
    correction = compose(globalOf(last), inverse(nodes[last].local));
    nodes_at_last_optimization = nodes.size();
    loops_since_optimization = false;
    stats.optimize_seconds += since(t0);
  }

  /// Which loop search a node gets. During the run: near, wide, or both. At the end of the log
  /// the nodes no later node will follow (those of the unfinished submaps), one in
  /// loop_every_n_nodes, are searched twice, against every finished submap in range that ended
  /// wide_min_node_gap nodes before them: first in the wide window (EndWide), whether or not
  /// loops were closed lately, then, after an optimisation has moved them, in the near window
  /// about their corrected poses (EndNear: every such submap that passes the overlap test, not
  /// only the nearest few). A revisit of a place seen long before, in the last minutes of a
  /// log, is otherwise closed only if the periodic wide search happens to run there, and by
  /// the few matches that one search finds.
  void searchEnd(Search search) {
    if (active.empty()) return;
    const std::size_t first = submaps[active.front()].anchor;
    for (std::size_t n = first; n < nodes.size(); ++n) {
      if (n % config.loop_every_n_nodes == 0) searchLoops(n, search);
    }
  }

  void searchLoops(std::size_t n, Search search) {
    const bool near =
        search == Search::Near || search == Search::NearAndWide || search == Search::EndNear;
    const bool wide =
        search == Search::Wide || search == Search::NearAndWide || search == Search::EndWide;
    const bool end = search == Search::EndWide || search == Search::EndNear;
    const auto t0 = Clock::now();
    const Node& node = nodes[n];
    const Pose2D g = globalOf(n);
    // The search scores a spread subset of the points (its cost is linear in them); the
    // refinement and the score threshold use them all.
    std::vector<Eigen::Vector2f> coarse;
    const std::size_t stride = (node.points.size() + config.loop_search_points - 1) /
                               std::max<std::size_t>(1, config.loop_search_points);
    for (std::size_t k = 0; k < node.points.size(); k += std::max<std::size_t>(1, stride))
      coarse.push_back(node.points[k]);
    struct Candidate {
      std::size_t submap;
      bool wide;
      double distance;
      Pose2D initial;  // the node's estimate in the submap's frame
    };
    std::vector<Candidate> near_list, wide_list;
    // The wide search is for a robot that has lost its map: only after a stretch of nodes
    // without any loop closure.
    const bool lost = end || n >= last_loop_node + config.wide_idle_nodes;
    for (std::size_t s = 0; s < submaps.size(); ++s) {
      Submap& sub = submaps[s];
      if (!sub.matcher) continue;
      // Submaps the local chain has just left need no loop edge: it is accurate there.
      if (sub.last_node + config.loop_min_node_gap > n) continue;
      if (search == Search::EndNear && sub.last_node + config.wide_min_node_gap > n) continue;
      const bool use_wide = wide && lost && sub.last_node + config.wide_min_node_gap <= n;
      if (!near && !use_wide) continue;
      const Pose2D ga = globalOf(sub.anchor), la = nodes[sub.anchor].local;
      const Pose2D local_to_global = compose(ga, inverse(la));
      const Eigen::Vector2f c = apply(local_to_global, sub.centre_local.cast<float>());
      const double distance = std::hypot(c.x() - g.x, c.y() - g.y);
      if (distance > config.loop_max_distance) continue;
      const Pose2D initial = compose(inverse(local_to_global), g);
      if (use_wide) {
        wide_list.push_back({s, true, distance, initial});
      } else if (overlap(*sub.grid, node.points, initial) >= config.loop_min_overlap) {
        near_list.push_back({s, false, distance, initial});
      }
    }
    // The nearest few submaps are enough to tie the node in; searching every one costs.
    std::sort(near_list.begin(), near_list.end(),
              [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
    if (search != Search::EndNear && near_list.size() > config.loop_max_submaps)
      near_list.resize(config.loop_max_submaps);
    near_list.insert(near_list.end(), wide_list.begin(), wide_list.end());
    for (const Candidate& cand : near_list) {
      const std::size_t s = cand.submap;
      Submap& sub = submaps[s];
      const bool use_wide = cand.wide;
      const Pose2D initial = cand.initial;
      const Pose2D la = nodes[sub.anchor].local;
      stats.loop_searches++;
      const std::optional<ScanMatch2D> m = sub.matcher->match(
          coarse, initial, use_wide ? config.wide_linear_window : config.loop_linear_window,
          (use_wide ? config.wide_angular_window_deg : config.loop_angular_window_deg) * kPi /
              180.0,
          config.loop_min_score);
      stats.loop_candidates += sub.matcher->lastCandidates();
      if (!m) continue;
      const MatchGrid grid(*sub.grid, table);
      const ScanMatch2D refined =
          refinePose(grid, node.points, m->pose, m->pose, config.translation_weight,
                     config.rotation_weight, config.refine_iterations, config.bicubic);
      if (refined.score < config.loop_min_score) continue;
      const std::size_t e =
          graph.addEdge(sub.anchor, n, compose(inverse(la), refined.pose), loop_information, true);
      loops.push_back({n, s, sub.anchor, refined.score, e});
      stats.loops_found++;
      last_loop_node = n;
      loops_since_optimization = true;
    }
    stats.loop_seconds += since(t0);
  }

  /// The poses a new scan is matched from, the prediction first. The prediction is the last
  /// pose moved by the odometry's motion since the last scan. A reading repeated while the
  /// robot moves is a stalled odometry that jumps by the whole motion when it resumes (the raw
  /// MIT CSAIL log stalls for 0.8 s at a time): the first fresh reading after a repeated one
  /// moves the pose of the scan where the repeated reading first came, and while a reading
  /// repeats, the scan is also matched at the last scan's motion (the better match wins).
  std::vector<Pose2D> predictions(const std::optional<Pose2D>& odometry, bool fresh) const {
    if (local.empty()) return {odometry ? *odometry : Pose2D{}};
    if (!odometry || !last_odometry) return {local.back()};
    if (!fresh) return {local.back(), compose(local.back(), last_motion)};
    const Pose2D step = compose(inverse(*last_odometry), *odometry);
    return {compose(odometry_repeated ? odometry_origin : local.back(), step)};
  }

  /// A scan matched against the older active submap from `from`: the correlative search in
  /// the local window, whose angular half-width grows with the turn `from` makes since the
  /// last scan (odometry's heading error grows with the turn), then Gauss-Newton. When `from`
  /// comes from a fresh odometry reading (`measured`), the weak directions keep it.
  ScanMatch2D matchLocal(const std::vector<Eigen::Vector2f>& points, const Pose2D& from,
                         bool measured) const {
    const Slam2DConfig& c = config;
    const MatchGrid grid(*submaps[active.front()].grid, table);
    const double turned =
        local.empty() ? 0.0 : std::fabs(std::remainder(from.theta - local.back().theta, 2 * kPi));
    const double window =
        c.local_angular_window_deg * kPi / 180.0 + c.local_angular_window_per_turn * turned;
    const ScanMatch2D coarse =
        correlativeSearch(grid, points, from, c.local_linear_window, std::min(window, kPi),
                          angularSearchStep(c.resolution, points));
    ScanMatch2D match = refinePose(grid, points, coarse.pose, coarse.pose, c.translation_weight,
                                   c.rotation_weight, c.refine_iterations, c.bicubic);
    // A scan that hardly prefers where it matched over where the prediction puts it (at the
    // match's heading) keeps the prediction along the directions it does not constrain.
    Pose2D at_prediction = match.pose;
    at_prediction.x = from.x;
    at_prediction.y = from.y;
    if (measured && c.weak_direction_weight > 0 &&
        match.score - scoreAt(grid, points, at_prediction) < c.weak_direction_min_gain) {
      const WeakDirectionPrior weak{Eigen::Vector2d(from.x, from.y), c.weak_direction_weight,
                                    c.weak_direction_information / (c.resolution * c.resolution)};
      match = refinePose(grid, points, match.pose, coarse.pose, c.translation_weight,
                         c.rotation_weight, c.refine_iterations, c.bicubic, &weak);
    }
    return match;
  }

  /// What the run holds in its large structures: submap grids, their loop-closure levels and
  /// the nodes' beams. Every grid growth is checked against the budget beside it.
  std::uint64_t heldBytes() const {
    std::uint64_t total = 0;
    for (const Submap& s : submaps) {
      total += s.grid->memoryBytes();
      if (s.matcher) total += s.matcher->bytes();
    }
    return total + node_bytes;
  }

  void insertNode(std::size_t n) {
    const auto t0 = Clock::now();
    const Node& node = nodes[n];
    if (active.empty() || submaps[active.back()].nodes >= config.scans_per_submap) {
      Submap s;
      s.grid = std::make_unique<LogOddsGrid2D>(submapParams(config));
      s.anchor = n;
      submaps.push_back(std::move(s));
      active.push_back(submaps.size() - 1);
      stats.submaps++;
    }
    std::vector<Eigen::Vector2f> ends;
    ends.reserve(node.ends.size());
    for (const Eigen::Vector2f& e : node.ends) ends.push_back(apply(node.local, e));
    const Eigen::Vector2f origin = apply(
        node.local, Eigen::Vector2f(static_cast<float>(sensor.x), static_cast<float>(sensor.y)));
    for (std::size_t s : active) {
      Submap& sub = submaps[s];
      sub.grid->setMemoryHeldElsewhere(heldBytes() - sub.grid->memoryBytes());
      sub.grid->insertScan(origin, ends);
      sub.centre_local = (sub.centre_local * static_cast<double>(sub.nodes) +
                          Eigen::Vector2d(node.local.x, node.local.y)) /
                         static_cast<double>(sub.nodes + 1);
      sub.nodes++;
      sub.last_node = n;
    }
    if (submaps[active.front()].nodes >= 2 * config.scans_per_submap) {
      Submap& done = submaps[active.front()];
      done.matcher = std::make_unique<BranchAndBoundMatcher2D>(
          MatchGrid(*done.grid, table), config.branch_and_bound_depth, heldBytes());
      active.pop_front();
      stats.finished_submaps++;
    }
    stats.insert_seconds += since(t0);
  }
};

Slam2D::Slam2D(const Slam2DConfig& config, const Pose2D& sensor_to_base) {
  validateSlam2DConfig(config);
  if (!std::isfinite(sensor_to_base.x) || !std::isfinite(sensor_to_base.y) ||
      !std::isfinite(sensor_to_base.theta))
    throw std::invalid_argument("the sensor's pose on the robot is not finite");
  impl_ = std::make_unique<Impl>(config, sensor_to_base);
}

Slam2D::~Slam2D() = default;

void Slam2D::addScan(const LaserScan& scan, const std::optional<Pose2D>& odometry, double stamp) {
  Impl& d = *impl_;
  if (d.finished) throw std::logic_error("Slam2D: addScan after finish");
  validateLaserScan(scan);
  if (scan.ranges.empty()) throw std::invalid_argument("scan has no beams");
  if (!std::isnan(stamp) && !std::isfinite(stamp))
    throw std::invalid_argument("stamp is infinite (NaN: no stamp)");
  if (odometry &&
      !(std::isfinite(odometry->x) && std::isfinite(odometry->y) && std::isfinite(odometry->theta)))
    throw std::invalid_argument("odometry pose is not finite");
  const auto t0 = Clock::now();
  const Slam2DConfig& c = d.config;
  Impl::Node node;
  node.scan = d.local.size();
  for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
    const double r = scan.ranges[k];
    double a = scan.angles[k];
    // Beyond max_range: no return (a logged maximum reading) or too uncertain to place.
    if (!(r >= c.min_range && r <= c.max_range) || !std::isfinite(a)) continue;
    const Eigen::Vector2f p = apply(d.sensor, Eigen::Vector2f(static_cast<float>(r * std::cos(a)),
                                                              static_cast<float>(r * std::sin(a))));
    node.ends.push_back(p);
  }
  node.points = voxelFilter(node.ends, c.voxel_filter);

  const bool fresh_odometry =
      odometry && (!d.last_odometry || odometry->x != d.last_odometry->x ||
                   odometry->y != d.last_odometry->y || odometry->theta != d.last_odometry->theta);
  const std::vector<Pose2D> hypotheses = d.predictions(odometry, fresh_odometry);
  const Pose2D& predicted = hypotheses.front();
  // A prediction beyond the grids' reach (2^30 cells of the finest resolution, and
  // well inside what the cell arithmetic holds) is refused before anything changes.
  const double reach = 1e6;
  if (!(std::fabs(predicted.x) <= reach && std::fabs(predicted.y) <= reach &&
        std::isfinite(predicted.theta))) {
    char msg[160];
    std::snprintf(msg, sizeof msg,
                  "odometry moves the robot beyond +-1e6 m (predicted position (%g, %g))",
                  predicted.x, predicted.y);
    throw std::invalid_argument(msg);
  }

  Pose2D pose = predicted;
  if (!d.active.empty() && !node.points.empty()) {
    // Hypotheses within the search window of the first one add nothing.
    const double lw = c.local_linear_window, aw = c.local_angular_window_deg * kPi / 180.0;
    ScanMatch2D best = d.matchLocal(node.points, predicted, fresh_odometry);
    for (std::size_t h = 1; h < hypotheses.size(); ++h) {
      const Pose2D delta = compose(inverse(predicted), hypotheses[h]);
      if (std::fabs(delta.x) <= lw && std::fabs(delta.y) <= lw && std::fabs(delta.theta) <= aw)
        continue;
      const ScanMatch2D other = d.matchLocal(node.points, hypotheses[h], fresh_odometry);
      if (other.score > best.score) best = other;
    }
    pose = best.pose;
  }
  if (fresh_odometry) {
    d.last_odometry = odometry;
    d.odometry_origin = pose;
    d.odometry_repeated = false;
  } else if (odometry) {
    d.odometry_repeated = true;
  }
  d.last_motion = d.local.empty() ? Pose2D{} : compose(inverse(d.local.back()), pose);
  d.local.push_back(pose);
  d.stats.scans++;
  d.stats.local_seconds += since(t0);

  // Motion filter.
  bool is_node = d.nodes.empty();
  if (!is_node) {
    const Pose2D& last = d.nodes.back().local;
    const double moved = std::hypot(pose.x - last.x, pose.y - last.y);
    const double turned = std::fabs(std::remainder(pose.theta - last.theta, 2 * kPi));
    is_node = moved >= c.node_min_distance || turned >= c.node_min_angle_deg * kPi / 180.0 ||
              std::fabs(stamp - d.last_node_stamp) >= c.node_max_time;
  }
  if (!is_node) {
    d.scan_node.push_back(d.nodes.size() - 1);
    return;
  }
  node.local = pose;
  d.last_node_stamp = stamp;
  const std::size_t n = d.nodes.size();
  d.node_bytes += (node.ends.capacity() + node.points.capacity()) * sizeof(Eigen::Vector2f);
  d.nodes.push_back(std::move(node));
  d.node_scans.push_back(d.nodes[n].scan);
  d.scan_node.push_back(n);
  d.stats.nodes++;
  d.graph.addVertex(static_cast<std::int64_t>(n), compose(d.correction, pose));
  if (n > 0) d.graph.addEdge(n - 1, n, compose(inverse(d.nodes[n - 1].local), pose), d.information);
  d.insertNode(n);
  const bool near = n % c.loop_every_n_nodes == 0, wide = n % c.wide_every_n_nodes == 0;
  if (near || wide)
    d.searchLoops(n, near && wide ? Impl::Search::NearAndWide
                                  : (near ? Impl::Search::Near : Impl::Search::Wide));
  if (d.loops_since_optimization &&
      d.nodes.size() - d.nodes_at_last_optimization >= c.optimize_every_n_nodes)
    d.optimizeGraph(c.optimize_iterations);
}

void Slam2D::finish() {
  Impl& d = *impl_;
  if (d.finished) return;
  d.finished = true;
  if (d.nodes.empty()) throw std::invalid_argument("no scan was added");
  d.final_round = true;
  // Search the end in the wide window, optimise, search it again in the near window about
  // the corrected poses, optimise.
  d.searchEnd(Impl::Search::EndWide);
  if (!d.loops.empty()) d.optimizeGraph(d.config.final_iterations);
  const std::size_t found = d.stats.loops_found;
  d.searchEnd(Impl::Search::EndNear);
  if (d.stats.loops_found != found) d.optimizeGraph(d.config.final_iterations);
  const auto t0 = Clock::now();
  d.map = std::make_unique<LogOddsGrid2D>(currentMap());
  d.stats.map_seconds += since(t0);
}

LogOddsGrid2D Slam2D::currentMap() const {
  const Impl& d = *impl_;
  if (d.map) return *d.map;
  if (d.nodes.empty()) throw std::invalid_argument("no scan was added: there is no map yet");
  LogOddsGrid2D map(d.config.map);
  map.setMemoryHeldElsewhere(d.heldBytes());
  std::vector<Eigen::Vector2f> ends;
  for (std::size_t n = 0; n < d.nodes.size(); ++n) {
    const Pose2D g = d.globalOf(n);
    ends.clear();
    for (const Eigen::Vector2f& e : d.nodes[n].ends) ends.push_back(apply(g, e));
    map.insertScan(
        apply(g, Eigen::Vector2f(static_cast<float>(d.sensor.x), static_cast<float>(d.sensor.y))),
        ends);
  }
  return map;
}

std::vector<Pose2D> Slam2D::trajectory() const {
  const Impl& d = *impl_;
  std::vector<Pose2D> out;
  out.reserve(d.local.size());
  for (std::size_t j = 0; j < d.local.size(); ++j) {
    const std::size_t n = d.scan_node[j];
    const Pose2D g = d.globalOf(n);
    out.push_back(compose(compose(g, inverse(d.nodes[n].local)), d.local[j]));
  }
  return out;
}

std::vector<Eigen::Vector2d> Slam2D::submapCentres() const {
  const Impl& d = *impl_;
  std::vector<Eigen::Vector2d> out;
  out.reserve(d.submaps.size());
  for (const Impl::Submap& s : d.submaps) {
    const Pose2D to_global = compose(d.globalOf(s.anchor), inverse(d.nodes[s.anchor].local));
    out.push_back(apply(to_global, s.centre_local.cast<float>()).cast<double>());
  }
  return out;
}

const PoseGraph2D& Slam2D::graph() const { return impl_->graph; }
const std::vector<std::size_t>& Slam2D::nodeScans() const { return impl_->node_scans; }
const std::vector<LoopClosure2D>& Slam2D::loops() const { return impl_->loops; }
const Slam2DStats& Slam2D::stats() const { return impl_->stats; }
const Slam2DConfig& Slam2D::config() const { return impl_->config; }

const LogOddsGrid2D& Slam2D::map() const {
  if (!impl_->map) throw std::logic_error("Slam2D: map before finish");
  return *impl_->map;
}

}  // namespace metricmap
