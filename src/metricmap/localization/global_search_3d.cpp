#include "metricmap/localization/global_search_3d.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "metricmap/localization/place_descriptor_3d.h"
#include "metricmap/localization/scan_ground_3d.h"
#include "metricmap/slam3d/loop_verification.h"

namespace metricmap {
namespace {

bool distinct(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const Localizer3DConfig& c) {
  const Eigen::Isometry3d d = a.inverse() * b;
  const double angle = Eigen::AngleAxisd(d.rotation()).angle() * 180.0 / M_PI;
  return d.translation().norm() > c.global_distinct_distance || angle > c.global_distinct_angle_deg;
}

/// The map's points within `radius` (horizontally) of `centre`.
std::vector<Eigen::Vector3f> around(const std::vector<Eigen::Vector3f>& map,
                                    const Eigen::Vector3d& centre, double radius) {
  std::vector<Eigen::Vector3f> out;
  const float cx = static_cast<float>(centre.x()), cy = static_cast<float>(centre.y());
  const float r2 = static_cast<float>(radius * radius);
  for (const Eigen::Vector3f& p : map) {
    const float dx = p.x() - cx, dy = p.y() - cy;
    if (dx * dx + dy * dy <= r2) out.push_back(p);
  }
  return out;
}

}  // namespace

LoopVerification verifyGuess(const std::vector<Eigen::Vector3d>& scan,
                             const std::vector<Eigen::Vector3f>& map_points,
                             const Eigen::Isometry3d& guess, const Localizer3DConfig& c) {
  std::vector<Eigen::Vector3f> query;
  query.reserve(scan.size());
  for (const Eigen::Vector3d& s : scan) query.push_back(s.cast<float>());
  const double crop = c.descriptor.max_radius + c.verify.max_correction;
  return verifyLoop(query, around(map_points, guess.translation(), crop), guess, c.verify);
}

GlobalSearch3D searchGlobally(const std::vector<Eigen::Vector3d>& scan,
                              const std::vector<Eigen::Vector3f>& map_points,
                              const std::vector<MapPlace3D>& places, const Localizer3DConfig& c) {
  GlobalSearch3D result;
  if (places.empty() || scan.size() < 50) return result;
  const ScanGround ground = estimateScanGround(scan, c.ground_threshold, c.ground_max_tilt_deg);
  const PlaceDescriptorParams dp{c.descriptor, c.clip_height, c.clip_slope};
  const ScanContext descriptor = scanDescriptor(scan, ground, dp);
  std::vector<ScanContextMatch> matches(places.size());
  for (std::size_t i = 0; i < places.size(); ++i)
    matches[i] = compareScanContexts(places[i].descriptor, descriptor);
  std::vector<std::size_t> order(places.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return matches[a].distance < matches[b].distance ||
           (matches[a].distance == matches[b].distance && a < b);
  });
  // One guess per neighbourhood: a place next to a chosen one adds nothing the ICP would not
  // reach from there.
  const double suppress = 1.5 * c.place_spacing;
  std::vector<std::size_t> chosen;
  for (std::size_t i : order) {
    if (static_cast<int>(chosen.size()) >= c.global_candidates) break;
    bool near = false;
    for (std::size_t j : chosen)
      near = near || (places[i].position - places[j].position).head<2>().norm() < suppress;
    if (!near) chosen.push_back(i);
  }
  struct Verified {
    Eigen::Isometry3d pose;
    double score;
    bool accepted;
  };
  std::vector<Verified> verified;
  for (std::size_t i : chosen) {
    const MapPlace3D& place = places[i];
    Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
    guess.translation() = place.position + Eigen::Vector3d(0, 0, ground.height);
    guess.linear() =
        Eigen::AngleAxisd(matches[i].yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
        ground.level;
    const LoopVerification v = verifyGuess(scan, map_points, guess, c);
    verified.push_back({v.relation, v.structure_overlap, v.accepted});
  }
  result.candidates = verified.size();
  const Verified* best = nullptr;
  for (const Verified& v : verified)
    if (v.accepted && (best == nullptr || v.score > best->score)) best = &v;
  if (best == nullptr) return result;
  double second = 0.0;
  for (const Verified& v : verified)
    if (&v != best && distinct(v.pose, best->pose, c)) second = std::max(second, v.score);
  result.pose = best->pose;
  result.score = best->score;
  result.margin = best->score - second;
  result.status = result.margin >= c.global_min_margin ? LocalizationStatus::Fixed
                                                       : LocalizationStatus::Ambiguous;
  return result;
}

}  // namespace metricmap
