// Pose-graph optimisation (Ceres, posegraph/) on the standard g2o sets in ../shared/data:
// chi² before and after, iterations and time, plain least squares (no robust loss, as g2o's
// published chi²). manhattan (and CSAIL) have no VERTEX lines: they start from the chained
// odometry guess. Each set is read once; every benchmark iteration optimises a fresh copy.
// The slow sets: run with --benchmark_repetitions=1 (one iteration each is registered).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "metricmap/posegraph/g2o_io.h"
#include "metricmap/posegraph/optimize.h"

namespace metricmap::bench {
namespace {

std::string g2oPath(const std::string& name) {
  return std::string(METRICMAP_SHARED_DATA_DIR) + "/posegraph_g2o/" + name;
}

template <typename Graph>
void run(benchmark::State& state, const Graph& graph, bool chained) {
  PoseGraphOptimizeOptions options;
  options.loop_loss = RobustLoss::None;
  options.max_iterations = static_cast<int>(state.range(0));
  options.threads = static_cast<int>(state.range(1));
  PoseGraphOptimizeResult r;
  double final_chi2 = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    Graph g = graph;
    state.ResumeTiming();
    r = optimize(g, options);
    final_chi2 = g.chi2();
    benchmark::DoNotOptimize(final_chi2);
  }
  state.counters["vertices"] = static_cast<double>(graph.vertexCount());
  state.counters["edges"] = static_cast<double>(graph.edgeCount());
  state.counters["chi2_initial"] = r.initial_chi2;
  state.counters["chi2_final"] = r.final_chi2;
  state.counters["iterations"] = r.iterations;
  state.counters["converged"] = r.termination == PoseGraphTermination::Converged ? 1 : 0;
  state.counters["chained_guess"] = chained ? 1 : 0;
  state.counters["solve_s"] = r.seconds;
  // The largest edge chi² at the end: a wrong basin leaves loop edges far from their measurements.
  Graph g = graph;
  optimize(g, options);
  double worst = 0.0;
  for (std::size_t i = 0; i < g.edgeCount(); ++i) worst = std::max(worst, g.edgeChi2(i));
  state.counters["max_edge_chi2"] = worst;
}

/// The file's poses replaced by the chained odometry guess (what readG2o gives a file without
/// VERTEX lines): vertex k = vertex k-1 composed with the first edge k-1 -> k. The ids must be
/// 0..n-1 in order, as in city10000.
PoseGraph2D chainOdometry(PoseGraph2D graph) {
  std::vector<const PoseGraph2D::Edge*> step(graph.vertexCount(), nullptr);
  for (const auto& e : graph.edges()) {
    if (e.to == e.from + 1 && step[e.to] == nullptr) step[e.to] = &e;
  }
  graph.setPose(0, Pose2D{});
  for (std::size_t k = 1; k < graph.vertexCount(); ++k) {
    if (step[k] == nullptr) throw std::runtime_error("no odometry edge to " + std::to_string(k));
    graph.setPose(k, compose(graph.vertex(k - 1).pose, step[k]->measurement));
  }
  return graph;
}

/// A 2D set's edges from the chained guess, though the file has VERTEX lines.
void BM_PoseGraphChained(benchmark::State& state, const std::string& name) {
  const std::string path = g2oPath(name);
  if (!std::filesystem::exists(path)) {
    state.SkipWithError((path + " is not available").c_str());
    for (auto _ : state) {
    }
    return;
  }
  run(state, chainOdometry(readG2o2D(path)), true);
}

void BM_PoseGraph(benchmark::State& state, const std::string& name) {
  const std::string path = g2oPath(name);
  if (!std::filesystem::exists(path)) {
    state.SkipWithError((path + " is not available").c_str());
    for (auto _ : state) {
    }
    return;
  }
  const G2oGraph g = readG2o(path);
  if (g.dimension == 2) {
    run(state, g.graph2d, g.chained_guess);
  } else {
    run(state, g.graph3d, g.chained_guess);
  }
}

// Args: max iterations (1000: to convergence; the library's default is 100), threads.
#define POSEGRAPH_BENCH(label, file)                        \
  BENCHMARK_CAPTURE(BM_PoseGraph, label, std::string(file)) \
      ->ArgsProduct({{1000}, {1}})                          \
      ->ArgNames({"max_it", "threads"})                     \
      ->Iterations(1)                                       \
      ->UseRealTime()                                       \
      ->Unit(benchmark::kMillisecond)

POSEGRAPH_BENCH(sphere2500, "sphere2500.g2o");
POSEGRAPH_BENCH(torus3D, "torus3D.g2o");
POSEGRAPH_BENCH(parking_garage, "parking-garage.g2o");
POSEGRAPH_BENCH(MIT, "MIT.g2o");
POSEGRAPH_BENCH(city10000, "city10000.g2o");
POSEGRAPH_BENCH(manhattan_chained, "manhattan.g2o");
POSEGRAPH_BENCH(CSAIL_chained, "CSAIL.g2o");
BENCHMARK_CAPTURE(BM_PoseGraphChained, city10000_chained, std::string("city10000.g2o"))
    ->ArgsProduct({{1000}, {1}})
    ->ArgNames({"max_it", "threads"})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PoseGraphChained, MIT_chained, std::string("MIT.g2o"))
    ->ArgsProduct({{1000}, {1}})
    ->ArgNames({"max_it", "threads"})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace metricmap::bench
