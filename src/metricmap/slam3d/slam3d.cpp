#include "metricmap/slam3d/slam3d.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "metricmap/common/rigid_transform.h"
#include "metricmap/posegraph/optimize.h"
#include "metricmap/registration/voxel_downsample.h"

namespace metricmap {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

Pose3D toPose(const Eigen::Isometry3d& t) {
  Pose3D p;
  p.translation = t.translation();
  p.rotation = Eigen::Quaterniond(t.rotation()).normalized();
  return p;
}

Eigen::Isometry3d toIsometry(const Pose3D& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = p.rotation.normalized().toRotationMatrix();
  t.translation() = p.translation;
  return t;
}

// Information of (translation, quaternion vector part): the vector part is half the angle.
PoseGraph3D::Information information(double sigma_m, double sigma_deg) {
  const double sr = sigma_deg * M_PI / 180.0 / 2.0;
  PoseGraph3D::Information info = PoseGraph3D::Information::Zero();
  for (int i = 0; i < 3; ++i) {
    info(i, i) = 1.0 / (sigma_m * sigma_m);
    info(i + 3, i + 3) = 1.0 / (sr * sr);
  }
  return info;
}

// The first point of each cell, as floats.
std::vector<Eigen::Vector3f> downsample(const Points3d& points, double voxel) {
  Points3d kept;
  voxelDownsample(points, voxel, kept);
  std::vector<Eigen::Vector3f> out(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) out[i] = kept[i].cast<float>();
  return out;
}

}  // namespace

Slam3D::Slam3D(const Slam3DConfig& config) : config_(config) {
  validateSlam3DConfig(config_);
  sc_params_.rings = config_.sc_rings;
  sc_params_.sectors = config_.sc_sectors;
  sc_params_.max_radius = config_.sc_max_radius;
  sc_params_.height_offset = config_.sc_height_offset;
  validateScanContextParams(sc_params_);
  verify_params_.coarse_threshold = config_.verify_coarse_threshold;
  verify_params_.fine_threshold = config_.verify_fine_threshold;
  verify_params_.map_voxel = std::max(config_.local_voxel, 0.5);
  verify_params_.overlap_distance = config_.verify_overlap_distance;
  verify_params_.min_overlap = config_.verify_min_overlap;
  verify_params_.min_structure_overlap = config_.verify_min_structure_overlap;
  verify_params_.max_correction = config_.verify_max_correction;
  validateLoopVerificationParams(verify_params_);
}

std::size_t Slam3D::bytes() const {
  std::size_t b = 0;
  for (const Node& n : nodes_) {
    b += n.points.capacity() * sizeof(Eigen::Vector3f) + sizeof(Node);
    b += static_cast<std::size_t>(n.descriptor.bins.size() + n.descriptor.ring_key.size()) *
         sizeof(float);
  }
  return b + poses_.capacity() * 2 * sizeof(Eigen::Isometry3d);
}

Slam3DFrameReport Slam3D::addScan(const pcl::PointCloud<pcl::PointXYZ>& scan,
                                  const Eigen::Isometry3d& odometry_pose) {
  if (finished_) throw std::logic_error("Slam3D::addScan after finish()");
  // Everything is checked before the first member changes: a refused scan leaves no trace.
  checkRigidTransform(odometry_pose.matrix(),
                      "Slam3D::addScan: odometry pose of node " + std::to_string(nodes_.size()));
  Slam3DFrameReport report;
  const std::size_t k = nodes_.size();
  report.node = k;
  Points3d in_range;
  in_range.reserve(scan.size());
  for (const pcl::PointXYZ& p : scan) {
    const Eigen::Vector3d q(p.x, p.y, p.z);
    if (!q.allFinite()) continue;
    const double r = q.norm();
    if (r >= config_.min_range && r <= config_.max_range) in_range.push_back(q);
  }
  Node node;
  node.points =
      in_range.empty() ? std::vector<Eigen::Vector3f>{} : downsample(in_range, config_.voxel);
  Eigen::Isometry3d pose = odometry_pose;
  if (k > 0) {
    const Eigen::Isometry3d step = odometry_.back().inverse() * odometry_pose;
    pose = poses_.back() * step;
    node.travel = nodes_.back().travel + step.translation().norm();
    checkRigidTransform(pose.matrix(), "Slam3D::addScan: map pose of node " + std::to_string(k));
  }
  nodes_.push_back(std::move(node));
  odometry_.push_back(odometry_pose);
  poses_.push_back(pose);
  graph_.addVertex(static_cast<std::int64_t>(k), toPose(pose));
  if (k > 0) {
    const Eigen::Isometry3d step = odometry_[k - 1].inverse() * odometry_pose;
    graph_.addEdge(k - 1, k, toPose(step),
                   information(config_.odometry_sigma_m, config_.odometry_sigma_deg));
  }
  // A node's local map is complete once `local_window` nodes follow it.
  while (next_search_ + config_.local_window < nodes_.size()) search(next_search_++, report);
  if (pending_ && nodes_.size() >= last_optimized_ + config_.optimize_every) optimizeGraph(report);
  return report;
}

Slam3DFrameReport Slam3D::finish() {
  Slam3DFrameReport report;
  if (finished_) return report;
  finished_ = true;
  report.node = nodes_.empty() ? 0 : nodes_.size() - 1;
  while (next_search_ < nodes_.size()) search(next_search_++, report);
  if (any_loop_ && (pending_ || last_optimized_ < nodes_.size())) optimizeGraph(report);
  return report;
}

std::vector<Eigen::Vector3f> Slam3D::localMap(std::size_t i) const {
  if (i >= nodes_.size()) throw std::out_of_range("Slam3D::localMap: no node " + std::to_string(i));
  const std::size_t w = config_.local_window;
  const std::size_t lo = i >= w ? i - w : 0, hi = std::min(nodes_.size() - 1, i + w);
  const Eigen::Isometry3d to_i = poses_[i].inverse();
  Points3d all;
  for (std::size_t j = lo; j <= hi; ++j) {
    const Eigen::Isometry3d t = to_i * poses_[j];
    for (const Eigen::Vector3f& p : nodes_[j].points) all.push_back(t * p.cast<double>());
  }
  if (all.empty()) return {};
  return downsample(all, config_.local_voxel);
}

std::vector<Slam3D::LoopCandidate> Slam3D::loopCandidates(std::size_t c,
                                                          std::size_t eligible) const {
  std::vector<LoopCandidate> candidates;
  // Radius search around the current estimate: the nearest eligible node.
  if (config_.loop_radius > 0.0 && eligible > 0) {
    double best = config_.loop_radius;
    std::size_t best_j = eligible;
    for (std::size_t j = 0; j < eligible; ++j) {
      const double d = (poses_[j].translation() - poses_[c].translation()).norm();
      if (d <= best) best = d, best_j = j;
    }
    if (best_j < eligible)
      candidates.push_back({best_j, poses_[best_j].inverse() * poses_[c], "radius", 1.0});
  }
  // Place recognition: nearest ring keys, then the full descriptor over every yaw.
  if (config_.sc_candidates > 0 && eligible > 0) {
    std::vector<std::pair<float, std::size_t>> keys;
    keys.reserve(eligible);
    for (std::size_t j = 0; j < eligible; ++j)
      keys.emplace_back(
          (nodes_[j].descriptor.ring_key - nodes_[c].descriptor.ring_key).squaredNorm(), j);
    const std::size_t n = std::min(keys.size(), config_.sc_candidates);
    std::partial_sort(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(n), keys.end());
    ScanContextMatch best;
    std::size_t best_j = eligible;
    for (std::size_t m = 0; m < n; ++m) {
      const ScanContextMatch match =
          compareScanContexts(nodes_[keys[m].second].descriptor, nodes_[c].descriptor);
      if (match.distance < best.distance) best = match, best_j = keys[m].second;
    }
    if (best_j < eligible && best.distance <= config_.sc_max_distance) {
      Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
      guess.linear() = Eigen::AngleAxisd(best.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      candidates.push_back({best_j, guess, "descriptor", best.distance});
    }
  }
  return candidates;
}

void Slam3D::search(std::size_t c, Slam3DFrameReport& report) {
  auto t0 = Clock::now();
  const std::vector<Eigen::Vector3f> local = localMap(c);
  Node& node = nodes_[c];
  node.descriptor = makeScanContext(local, sc_params_);
  node.described = true;
  timing_.descriptors += since(t0);
  if (c % config_.loop_every != 0) return;
  if (any_loop_ && c < last_loop_node_ + config_.loop_cooldown) return;
  ++report.searched;
  t0 = Clock::now();
  // Eligible: described nodes far enough back along the path.
  std::size_t eligible = 0;
  while (eligible < c && node.travel - nodes_[eligible].travel >= config_.loop_min_travel)
    ++eligible;
  const std::vector<LoopCandidate> candidates = loopCandidates(c, eligible);
  const double searched = since(t0);
  timing_.search += searched;
  report.seconds_search += searched;
  if (candidates.empty()) return;
  t0 = Clock::now();
  for (const LoopCandidate& cand : candidates) {
    Slam3DLoop loop;
    loop.from = cand.j;
    loop.to = c;
    loop.method = cand.method;
    loop.descriptor_distance = cand.distance;
    loop.check = verifyLoop(local, localMap(cand.j), cand.guess, verify_params_);
    ++report.candidates;
    const bool ok = loop.check.accepted;
    checks_.push_back(loop);
    if (!ok) continue;
    graph_.addEdge(cand.j, c, toPose(loop.check.relation),
                   information(config_.loop_sigma_m, config_.loop_sigma_deg), true);
    ++verified_;
    ++report.verified;
    any_loop_ = true;
    pending_ = true;
    last_loop_node_ = c;
    break;
  }
  const double verified = since(t0);
  timing_.verify += verified;
  report.seconds_verify += verified;
}

void Slam3D::optimizeGraph(Slam3DFrameReport& report) {
  const auto t0 = Clock::now();
  PoseGraphOptimizeOptions options;
  options.max_iterations = config_.max_iterations;
  options.loop_loss = RobustLoss::Huber;
  const PoseGraphOptimizeResult r = optimize(graph_, options);
  if (r.termination != PoseGraphTermination::Failure) {
    for (std::size_t i = 0; i < poses_.size(); ++i) poses_[i] = toIsometry(graph_.vertex(i).pose);
  }
  pending_ = false;
  last_optimized_ = nodes_.size();
  report.optimized = true;
  const double s = since(t0);
  timing_.optimize += s;
  ++timing_.optimizations;
  report.seconds_optimize += s;
}

}  // namespace metricmap
