// metricmap posegraph IN.g2o [--out OUT.g2o]: a 2D or 3D pose graph optimised with Ceres
// (robust loss on loop edges), with its chi² before and after.
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/output_set.h"
#include "metricmap/posegraph/g2o_io.h"
#include "metricmap/posegraph/optimize.h"

namespace metricmap::cli {
namespace {

struct PoseGraphOptions {
  std::string input, out, loop_loss = "huber", format = "table";
  int max_iterations = 1000;
  unsigned threads = 1;
  double loss_scale = 0.0;
};

void run(const PoseGraphOptions& o) {
  G2oGraph g = readG2o(o.input);
  PoseGraphOptimizeOptions opt;
  opt.max_iterations = o.max_iterations;
  opt.threads = static_cast<int>(o.threads);
  opt.loop_loss = parseRobustLoss(o.loop_loss);
  opt.loss_scale = o.loss_scale;
  const bool planar = g.dimension == 2;
  const std::size_t n_vertices = planar ? g.graph2d.vertexCount() : g.graph3d.vertexCount();
  const std::size_t n_edges = planar ? g.graph2d.edgeCount() : g.graph3d.edgeCount();
  if (n_edges == 0) {
    throw InputError(o.input + ": " + std::to_string(n_vertices) +
                     " vertices and no edge: nothing to optimise");
  }
  // Priced before Ceres builds anything (the budget): the estimate optimize() checks.
  checkMemory(
      1, planar ? solverMemoryBytes(g.graph2d) : solverMemoryBytes(g.graph3d),
      o.input + ": the solver (" + std::to_string(n_vertices) + " vertices, " +
          std::to_string(n_edges) + " edges, " +
          std::to_string(planar ? jacobianNonzeros(g.graph2d) : jacobianNonzeros(g.graph3d)) +
          " Jacobian nonzeros)");
  const PoseGraphOptimizeResult r = planar ? optimize(g.graph2d, opt) : optimize(g.graph3d, opt);
  if (r.termination == PoseGraphTermination::Failure) {
    throw InputError(o.input + ": the optimisation failed: " + r.message);
  }
  OutputSet outputs;  // committed once the report is printed
  if (!o.out.empty()) {
    if (planar) {
      writeG2o(outputs.stage(o.out), g.graph2d);
    } else {
      writeG2o(outputs.stage(o.out), g.graph3d);
    }
  }
  const std::size_t vertices = planar ? g.graph2d.vertexCount() : g.graph3d.vertexCount();
  const std::size_t edges = planar ? g.graph2d.edgeCount() : g.graph3d.edgeCount();
  const nlohmann::json j = {{"input", o.input},
                            {"dimension", g.dimension},
                            {"vertices", vertices},
                            {"edges", edges},
                            {"initial_guess", g.chained_guess ? "chained odometry" : "vertices"},
                            {"initial_chi2", r.initial_chi2},
                            {"final_chi2", r.final_chi2},
                            {"iterations", r.iterations},
                            {"termination", terminationName(r.termination)},
                            {"loop_loss", robustLossName(opt.loop_loss)},
                            {"linear_solver", r.linear_solver},
                            {"seconds", r.seconds}};
  if (o.format == "json") {
    emit(j.dump(2) + "\n", outputs);
    return;
  }
  char text[512];
  std::snprintf(text, sizeof text,
                "%s: %dD, %zu vertices, %zu edges (initial guess: %s)\n"
                "chi2 %.6g -> %.6g in %d iterations (%s), %.3f s, %s\n",
                o.input.c_str(), g.dimension, vertices, edges,
                g.chained_guess ? "chained odometry" : "the file's vertices", r.initial_chi2,
                r.final_chi2, r.iterations,
                r.termination == PoseGraphTermination::Converged
                    ? "converged"
                    : "stopped at --max-iterations without converging",
                r.seconds, r.linear_solver.c_str());
  emit(text, outputs);
}

}  // namespace

void addPoseGraphCommand(CLI::App& app) {
  auto o = std::make_shared<PoseGraphOptions>();
  CLI::App* sub = app.add_subcommand(
      "posegraph", "Optimise a g2o pose graph (SE(2) or SE(3)) with Ceres; chi² before and after");
  sub->add_option("input", o->input,
                  "g2o file (VERTEX_SE2/EDGE_SE2 or VERTEX_SE3:QUAT/"
                  "EDGE_SE3:QUAT; without vertices: chained from odometry)")
      ->required();
  sub->add_option("--out", o->out, "The optimised graph as a g2o file")->check(kOutputFile);
  sub->add_option("--max-iterations", o->max_iterations, "Levenberg-Marquardt iterations")
      ->check(countIn(1, 100000))
      ->capture_default_str();
  sub->add_option("--threads", o->threads, "Ceres' threads")
      ->check(countIn(1, 256))
      ->capture_default_str();
  sub->add_option("--loop-loss", o->loop_loss,
                  "Robust loss of loop edges (edges other than i -> i+1): none, huber, cauchy")
      ->check(CLI::IsMember({"none", "huber", "cauchy"}))
      ->capture_default_str();
  sub->add_option("--loss-scale", o->loss_scale,
                  "Scale of the robust loss (chi distance; default: the 99% point of chi² for the "
                  "edge's dimension)")
      ->check(finiteIn(1e-6, 1e6));
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    refuseIgnored(*sub, "--loss-scale", o->loop_loss != "none", "with --loop-loss none");
    requireDistinctFiles({{"input", o->input}}, {{"--out", o->out}});
    requireExtension("--out", o->out, {".g2o"}, "a g2o graph");
    run(*o);
  });
}

}  // namespace metricmap::cli
