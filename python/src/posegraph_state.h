#pragma once
/// \file posegraph_state.h
/// \brief A pose graph (2D or 3D) as a tuple of numpy arrays for pickle, and back; equality.
/// The tuple: ids (V,) int64, poses (V, P), fixed (V,) int64, ends (E, 2) int64,
/// measurements (E, P), information (E, D, D), loop (E,) int64 (P = 3 or 7 numbers a pose).

#include <stdexcept>
#include <vector>

#include "arrays.h"
#include "metricmap/posegraph/pose_graph.h"

namespace metricmap::python {

namespace pose_state {

inline void put(std::vector<double>& out, const Pose2D& p) {
  out.insert(out.end(), {p.x, p.y, p.theta});
}
inline void put(std::vector<double>& out, const Pose3D& p) {
  const Eigen::Quaterniond& q = p.rotation;
  out.insert(out.end(),
             {p.translation.x(), p.translation.y(), p.translation.z(), q.x(), q.y(), q.z(), q.w()});
}
inline Pose2D get(const double* d, Pose2D) { return {d[0], d[1], d[2]}; }
inline Pose3D get(const double* d, Pose3D) {
  Pose3D p;
  p.translation = Eigen::Vector3d(d[0], d[1], d[2]);
  p.rotation = Eigen::Quaterniond(d[6], d[3], d[4], d[5]);
  return p;
}
inline py::ssize_t numbers(const Pose2D&) { return 3; }
inline py::ssize_t numbers(const Pose3D&) { return 7; }
inline bool same(const Pose2D& a, const Pose2D& b) {
  return a.x == b.x && a.y == b.y && a.theta == b.theta;
}
inline bool same(const Pose3D& a, const Pose3D& b) {
  return a.translation == b.translation && a.rotation.coeffs() == b.rotation.coeffs();
}

}  // namespace pose_state

template <typename Pose, int D>
py::tuple poseGraphState(const PoseGraph<Pose, D>& g) {
  std::vector<std::int64_t> ids, fixed, ends, loop;
  std::vector<double> poses, measurements, information;
  for (const auto& v : g.vertices()) {
    ids.push_back(v.id);
    fixed.push_back(v.fixed ? 1 : 0);
    pose_state::put(poses, v.pose);
  }
  for (const auto& e : g.edges()) {
    ends.insert(ends.end(), {static_cast<std::int64_t>(e.from), static_cast<std::int64_t>(e.to)});
    loop.push_back(e.loop ? 1 : 0);
    pose_state::put(measurements, e.measurement);
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) information.push_back(e.information(r, c));
  }
  const py::ssize_t v = py::ssize_t(ids.size()), e = py::ssize_t(loop.size());
  const py::ssize_t p = pose_state::numbers(Pose{});
  return py::make_tuple(arrayFrom(ids, {v}), arrayFrom(poses, {v, p}), arrayFrom(fixed, {v}),
                        arrayFrom(ends, {e, 2}), arrayFrom(measurements, {e, p}),
                        arrayFrom(information, {e, py::ssize_t(D), py::ssize_t(D)}),
                        arrayFrom(loop, {e}));
}

/// \throws py::value_error naming `what` for a tuple that is not a pose graph's state
template <typename Pose, int D>
PoseGraph<Pose, D> poseGraphFrom(const py::tuple& t, const std::string& what) {
  constexpr int kC = py::array::c_style | py::array::forcecast;
  const auto bad = [&what]() { return py::value_error(what + ": not a pickled pose graph"); };
  if (t.size() != 7) throw bad();
  const auto ids = py::array_t<std::int64_t, kC>(t[0]);
  const auto poses = py::array_t<double, kC>(t[1]);
  const auto fixed = py::array_t<std::int64_t, kC>(t[2]);
  const auto ends = py::array_t<std::int64_t, kC>(t[3]);
  const auto measurements = py::array_t<double, kC>(t[4]);
  const auto information = py::array_t<double, kC>(t[5]);
  const auto loop = py::array_t<std::int64_t, kC>(t[6]);
  const py::ssize_t v = ids.size(), e = loop.size(), p = pose_state::numbers(Pose{});
  if (poses.size() != v * p || fixed.size() != v || ends.size() != 2 * e ||
      measurements.size() != e * p || information.size() != e * D * D)
    throw bad();
  PoseGraph<Pose, D> g;
  for (py::ssize_t k = 0; k < v; ++k) {
    g.addVertex(ids.data()[k], pose_state::get(poses.data() + k * p, Pose{}));
    g.setFixed(static_cast<std::size_t>(k), fixed.data()[k] != 0);
  }
  for (py::ssize_t k = 0; k < e; ++k) {
    typename PoseGraph<Pose, D>::Information info;
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) info(r, c) = information.data()[(k * D + r) * D + c];
    const std::int64_t from = ends.data()[2 * k], to = ends.data()[2 * k + 1];
    if (from < 0 || to < 0) throw bad();
    g.addEdge(static_cast<std::size_t>(from), static_cast<std::size_t>(to),
              pose_state::get(measurements.data() + k * p, Pose{}), info, loop.data()[k] != 0);
  }
  return g;
}

template <typename Pose, int D>
bool samePoseGraph(const PoseGraph<Pose, D>& a, const PoseGraph<Pose, D>& b) {
  if (a.vertices().size() != b.vertices().size() || a.edges().size() != b.edges().size())
    return false;
  for (std::size_t k = 0; k < a.vertices().size(); ++k) {
    const auto &x = a.vertices()[k], &y = b.vertices()[k];
    if (x.id != y.id || x.fixed != y.fixed || !pose_state::same(x.pose, y.pose)) return false;
  }
  for (std::size_t k = 0; k < a.edges().size(); ++k) {
    const auto &x = a.edges()[k], &y = b.edges()[k];
    if (x.from != y.from || x.to != y.to || x.loop != y.loop || x.information != y.information ||
        !pose_state::same(x.measurement, y.measurement))
      return false;
  }
  return true;
}

}  // namespace metricmap::python
