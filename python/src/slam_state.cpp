#include "slam_state.h"

#include <string>
#include <utility>

#include <pybind11/stl.h>

#include "posegraph_state.h"

namespace metricmap::python {

namespace {

constexpr int kC = py::array::c_style | py::array::forcecast;

[[noreturn]] void notAState() { throw py::value_error("Slam2D: not a pickled Slam2D"); }

py::array_t<double> posesOf(const std::vector<Pose2D>& poses) {
  std::vector<double> v;
  for (const Pose2D& p : poses) v.insert(v.end(), {p.x, p.y, p.theta});
  return arrayFrom(v, {py::ssize_t(poses.size()), 3});
}

std::vector<Pose2D> posesFrom(const py::handle& obj) {
  const auto a = py::array_t<double, kC>::ensure(obj);
  if (!a || a.ndim() != 2 || a.shape(1) != 3) notAState();
  std::vector<Pose2D> out;
  for (py::ssize_t k = 0; k < a.shape(0); ++k) out.push_back({a.at(k, 0), a.at(k, 1), a.at(k, 2)});
  return out;
}

py::tuple statsState(const Slam2DStats& s) {
  return py::make_tuple(s.scans, s.nodes, s.submaps, s.finished_submaps, s.loop_searches,
                        s.loop_candidates, s.loops_found, s.loops_rejected, s.optimizations,
                        s.local_seconds, s.insert_seconds, s.loop_seconds, s.optimize_seconds,
                        s.map_seconds, s.final_chi2_initial, s.final_chi2, s.final_iterations);
}

Slam2DStats statsFrom(const py::tuple& t) {
  if (t.size() != 17) notAState();
  Slam2DStats s;
  std::size_t* counts[] = {
      &s.scans,           &s.nodes,       &s.submaps,        &s.finished_submaps, &s.loop_searches,
      &s.loop_candidates, &s.loops_found, &s.loops_rejected, &s.optimizations};
  for (std::size_t k = 0; k < 9; ++k) *counts[k] = t[k].cast<std::size_t>();
  double* seconds[] = {&s.local_seconds,    &s.insert_seconds, &s.loop_seconds,
                       &s.optimize_seconds, &s.map_seconds,    &s.final_chi2_initial,
                       &s.final_chi2};
  for (std::size_t k = 0; k < 7; ++k) *seconds[k] = t[9 + k].cast<double>();
  s.final_iterations = t[16].cast<int>();
  return s;
}

py::tuple gridState(const LogOddsGrid2D& g) {
  const LogOddsParams& p = g.params();
  const std::vector<float> cells(g.data(), g.data() + g.width() * g.height());
  return py::make_tuple(py::make_tuple(p.resolution, p.prob_hit, p.prob_miss, p.clamp_min,
                                       p.clamp_max, p.occupancy_threshold, p.max_range),
                        g.minI(), g.minJ(), g.width(), g.height(),
                        arrayFrom(cells, {py::ssize_t(cells.size())}));
}

std::unique_ptr<LogOddsGrid2D> gridFrom(const py::tuple& t) {
  if (t.size() != 6) notAState();
  const auto q = t[0].cast<std::vector<double>>();
  if (q.size() != 7) notAState();
  const auto cells = py::array_t<float, kC>(t[5]);
  return std::make_unique<LogOddsGrid2D>(
      LogOddsParams{q[0], q[1], q[2], q[3], q[4], q[5], q[6]}, t[1].cast<std::int64_t>(),
      t[2].cast<std::int64_t>(), t[3].cast<std::int64_t>(), t[4].cast<std::int64_t>(),
      std::vector<float>(cells.data(), cells.data() + cells.size()));
}

}  // namespace

void PySlam::keepResult() {
  auto r = std::make_unique<Slam2DResult>();
  r->config = slam->config();
  r->trajectory = slam->trajectory();
  r->node_scans = slam->nodeScans();
  r->loops = slam->loops();
  r->graph = slam->graph();
  r->stats = slam->stats();
  r->map = std::make_unique<LogOddsGrid2D>(slam->map());
  result = std::move(r);
  slam.reset();
}

const Slam2DResult& PySlam::finishedResult() const {
  if (!result) throw py::value_error("the map is built by finish(): call it first");
  return *result;
}

py::tuple slamState(const PySlam& p) {
  ObjectGuard guard(p.mutex, "Slam2D");
  if (!p.result)
    throw py::type_error(
        "a Slam2D pickles once finished (its working state is not saved): "
        "call finish() first");
  const Slam2DResult& r = *p.result;
  std::vector<std::int64_t> nodes(r.node_scans.begin(), r.node_scans.end());
  py::list loops;
  for (const LoopClosure2D& l : r.loops)
    loops.append(py::make_tuple(l.node, l.submap, l.anchor, l.score, l.edge));
  return py::make_tuple(py::cast(r.config), posesOf(r.trajectory),
                        arrayFrom(p.stamps, {py::ssize_t(p.stamps.size())}),
                        arrayFrom(nodes, {py::ssize_t(nodes.size())}), loops,
                        poseGraphState(r.graph), statsState(r.stats), gridState(*r.map));
}

std::unique_ptr<PySlam> slamFromState(const py::tuple& t) {
  if (t.size() != 8) notAState();
  auto r = std::make_unique<Slam2DResult>();
  r->config = t[0].cast<Slam2DConfig>();
  r->trajectory = posesFrom(t[1]);
  const auto stamps = py::array_t<double, kC>(t[2]);
  const auto nodes = py::array_t<std::int64_t, kC>(t[3]);
  for (py::ssize_t k = 0; k < nodes.size(); ++k)
    r->node_scans.push_back(static_cast<std::size_t>(nodes.data()[k]));
  for (const py::handle& l : t[4].cast<py::list>()) {
    const py::tuple e = l.cast<py::tuple>();
    if (e.size() != 5) notAState();
    r->loops.push_back({e[0].cast<std::size_t>(), e[1].cast<std::size_t>(),
                        e[2].cast<std::size_t>(), e[3].cast<double>(), e[4].cast<std::size_t>()});
  }
  r->graph = poseGraphFrom<Pose2D, 3>(t[5].cast<py::tuple>(), "Slam2D");
  r->stats = statsFrom(t[6].cast<py::tuple>());
  r->map = gridFrom(t[7].cast<py::tuple>());
  auto p = std::make_unique<PySlam>();
  p->stamps.assign(stamps.data(), stamps.data() + stamps.size());
  p->result = std::move(r);
  return p;
}

}  // namespace metricmap::python
