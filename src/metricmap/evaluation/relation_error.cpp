#include "metricmap/evaluation/relation_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "metricmap/evaluation/pose_pairing.h"
#include "metricmap/evaluation/rotation_angle.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

/// A trajectory's stamps in increasing order (raw logs step back), with the poses' indices.
struct SortedStamps {
  std::vector<std::size_t> order;
  std::vector<double> stamps;
};

SortedStamps sortedStamps(const Trajectory& t, const char* what) {
  if (!t.hasStamps())
    throw std::invalid_argument(std::string("the relation metric needs ") + what +
                                " with time stamps");
  if (t.stamps.size() != t.size())
    throw std::invalid_argument(std::string(what) + " has " + std::to_string(t.stamps.size()) +
                                " stamps for " + std::to_string(t.size()) + " poses");
  SortedStamps s;
  s.order.resize(t.size());
  std::iota(s.order.begin(), s.order.end(), std::size_t{0});
  std::stable_sort(s.order.begin(), s.order.end(),
                   [&](std::size_t a, std::size_t b) { return t.stamps[a] < t.stamps[b]; });
  s.stamps.resize(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    s.stamps[k] = t.stamps[s.order[k]];
    if (!std::isfinite(s.stamps[k]))
      throw std::invalid_argument(std::string(what) + " has a stamp that is not finite");
  }
  return s;
}

std::optional<Eigen::Isometry3d> poseAt(const Trajectory& t, const SortedStamps& s, double at,
                                        double max_extrapolation) {
  const std::vector<double>& st = s.stamps;
  if (st.empty() || at < st.front() - max_extrapolation || at > st.back() + max_extrapolation)
    return std::nullopt;
  if (at <= st.front()) return t.poses[s.order.front()];
  if (at >= st.back()) return t.poses[s.order.back()];
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(st.begin(), st.end(), at) -
                                                  st.begin());  // st[hi - 1] <= at < st[hi]
  const Eigen::Isometry3d& a = t.poses[s.order[hi - 1]];
  const Eigen::Isometry3d& b = t.poses[s.order[hi]];
  const double span = st[hi] - st[hi - 1];
  const double f = span > 0 ? (at - st[hi - 1]) / span : 0.0;
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = a.translation() + f * (b.translation() - a.translation());
  out.linear() = Eigen::Quaterniond(a.linear())
                     .slerp(f, Eigen::Quaterniond(b.linear()))
                     .normalized()
                     .toRotationMatrix();
  return out;
}

}  // namespace

std::optional<Eigen::Isometry3d> poseAtStamp(const Trajectory& trajectory, double t,
                                             double max_extrapolation) {
  return poseAt(trajectory, sortedStamps(trajectory, "the trajectory"), t, max_extrapolation);
}

RelationError relationError(const Trajectory& estimate, const std::vector<PoseRelation>& relations,
                            double max_time_diff, const Trajectory* odometry) {
  const SortedStamps est = sortedStamps(estimate, "the estimate");
  SortedStamps odo;
  if (odometry) odo = sortedStamps(*odometry, "the odometry");
  // The estimate's pose at a relation stamp: its own within max_time_diff, else (with
  // odometry) the nearest one moved by the odometry.
  std::size_t interpolated = 0;
  auto poseFor = [&](double t) -> std::optional<Eigen::Isometry3d> {
    const std::size_t n = nearestStamp(est.stamps, t, max_time_diff);
    if (n < est.stamps.size()) return estimate.poses[est.order[n]];
    if (!odometry) return std::nullopt;
    const std::size_t m = nearestStamp(est.stamps, t, std::numeric_limits<double>::infinity());
    const double tn = est.stamps[m];
    const auto o_n = poseAt(*odometry, odo, tn, max_time_diff);
    const auto o_t = poseAt(*odometry, odo, t, max_time_diff);
    if (!o_n || !o_t) return std::nullopt;
    ++interpolated;
    return estimate.poses[est.order[m]] * (o_n->inverse() * *o_t);
  };
  RelationError e;
  std::vector<double> t_sq, r_sq;
  for (std::size_t k = 0; k < relations.size(); ++k) {
    const PoseRelation& r = relations[k];
    const std::optional<Eigen::Isometry3d> pi = poseFor(r.stamp1), pj = poseFor(r.stamp2);
    if (!pi || !pj) {
      e.skipped.push_back(k);
      continue;
    }
    const Eigen::Isometry3d delta = pi->inverse() * *pj;
    const Eigen::Isometry3d err = r.relative.inverse() * delta;
    e.used_relations.push_back(k);
    e.translation.push_back(err.translation().norm());
    e.rotation_deg.push_back(rotationAngleDeg(err.linear()));
    t_sq.push_back(e.translation.back() * e.translation.back());
    r_sq.push_back(e.rotation_deg.back() * e.rotation_deg.back());
  }
  e.used = e.translation.size();
  if (e.used == 0) {  // no relation measured: a mean of 0 would read as a perfect estimate
    std::ostringstream msg;
    msg << "none of the " << relations.size() << " relations has both stamps within "
        << max_time_diff << " s of a stamp of the estimate"
        << (odometry ? " or within the span of the odometry" : "") << ": nothing to measure";
    throw InputError(msg.str());
  }
  e.interpolated = interpolated;
  e.translation_abs = meanAndSampleStd(e.translation);
  e.translation_sq = meanAndSampleStd(t_sq);
  e.rotation_abs_deg = meanAndSampleStd(e.rotation_deg);
  e.rotation_sq_deg = meanAndSampleStd(r_sq);
  return e;
}

}  // namespace metricmap
