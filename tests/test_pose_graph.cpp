// Pose graphs (posegraph/): the Ceres optimiser against a dense Gauss-Newton written here, g2o
// round trips, the chained initial guess, hostile g2o input, and the real benchmark sets.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "metricmap/exceptions.h"
#include "metricmap/posegraph/g2o_io.h"
#include "metricmap/posegraph/optimize.h"
#include "metricmap/posegraph/pose_graph.h"
#include "scratch_files.h"
#include "shared_data.h"

namespace {

using metricmap::G2oGraph;
using metricmap::InputError;
using metricmap::Pose2D;
using metricmap::Pose3D;
using metricmap::PoseGraph2D;
using metricmap::PoseGraph3D;
using metricmap::PoseGraphOptimizeOptions;
using metricmap::RobustLoss;

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

std::string sharedG2o(const std::string& name) {
  return std::string(METRICMAP_SHARED_DATA_DIR) + "/posegraph_g2o/" + name;
}

#define SKIP_UNLESS_EXISTS(path) SKIP_WITHOUT_SHARED_DATA(path)

/// A fresh directory for this process's files.
fs::path scratchDir() {
  static const metricmap::test_support::ScratchDir dir("metricmap_pose_graph_");  // removed at exit
  return dir.path;
}

std::string writeScratch(const std::string& name, const std::string& text) {
  const std::string path = (scratchDir() / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// ---------------------------------------------------------------------------------------------
// The independent oracle: g2o's SE(2) error through Eigen's Isometry2d, numeric Jacobians,
// dense Gauss-Newton.

Eigen::Isometry2d iso(double x, double y, double theta) {
  Eigen::Isometry2d t = Eigen::Isometry2d::Identity();
  t.translate(Eigen::Vector2d(x, y));
  t.rotate(Eigen::Rotation2Dd(theta));
  return t;
}

/// z⁻¹ (x_i⁻¹ x_j) as (x, y, angle in (-π, π]).
Eigen::Vector3d oracleError(const double* xi, const double* xj, const Pose2D& z) {
  const Eigen::Isometry2d d = iso(z.x, z.y, z.theta).inverse() *
                              (iso(xi[0], xi[1], xi[2]).inverse() * iso(xj[0], xj[1], xj[2]));
  return {d.translation().x(), d.translation().y(), std::atan2(d.linear()(1, 0), d.linear()(0, 0))};
}

double oracleChi2(const PoseGraph2D& g, const std::vector<double>& x) {
  double sum = 0.0;
  for (const auto& e : g.edges()) {
    const Eigen::Vector3d r = oracleError(&x[3 * e.from], &x[3 * e.to], e.measurement);
    sum += r.dot(e.information * r);
  }
  return sum;
}

/// Dense Gauss-Newton over all vertices but the first (fixed); Jacobians by central differences.
std::vector<double> denseGaussNewton(const PoseGraph2D& g, int* iterations) {
  const std::size_t n = g.vertexCount();
  std::vector<double> x(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    x[3 * i] = g.vertex(i).pose.x;
    x[3 * i + 1] = g.vertex(i).pose.y;
    x[3 * i + 2] = g.vertex(i).pose.theta;
  }
  const Eigen::Index m = static_cast<Eigen::Index>(3 * (n - 1));  // unknowns: vertices 1..n-1
  constexpr double h = 1e-6;
  for (*iterations = 1; *iterations <= 50; ++*iterations) {
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m, m);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
    for (const auto& e : g.edges()) {
      double xi[3] = {x[3 * e.from], x[3 * e.from + 1], x[3 * e.from + 2]};
      double xj[3] = {x[3 * e.to], x[3 * e.to + 1], x[3 * e.to + 2]};
      const Eigen::Vector3d r = oracleError(xi, xj, e.measurement);
      Eigen::Matrix<double, 3, 6> J;
      for (int k = 0; k < 6; ++k) {
        double* p = k < 3 ? &xi[k] : &xj[k - 3];
        const double keep = *p;
        *p = keep + h;
        const Eigen::Vector3d plus = oracleError(xi, xj, e.measurement);
        *p = keep - h;
        const Eigen::Vector3d minus = oracleError(xi, xj, e.measurement);
        *p = keep;
        J.col(k) = (plus - minus) / (2 * h);
      }
      const std::size_t vertex[2] = {e.from, e.to};
      for (int a = 0; a < 2; ++a) {
        if (vertex[a] == 0) continue;
        const Eigen::Index ra = static_cast<Eigen::Index>(3 * (vertex[a] - 1));
        const Eigen::Matrix<double, 3, 3> Ja = J.middleCols<3>(3 * a);
        b.segment<3>(ra) += Ja.transpose() * e.information * r;
        for (int c = 0; c < 2; ++c) {
          if (vertex[c] == 0) continue;
          const Eigen::Index rc = static_cast<Eigen::Index>(3 * (vertex[c] - 1));
          H.block<3, 3>(ra, rc) += Ja.transpose() * e.information * J.middleCols<3>(3 * c);
        }
      }
    }
    const Eigen::VectorXd dx = H.ldlt().solve(-b);
    for (Eigen::Index k = 0; k < m; ++k) x[static_cast<std::size_t>(3 + k)] += dx[k];
    if (dx.lpNorm<Eigen::Infinity>() < 1e-11) break;
  }
  return x;
}

/// MIT.g2o's vertices with id < `count` and the edges among them.
PoseGraph2D mitPrefix(const PoseGraph2D& mit, std::int64_t count) {
  PoseGraph2D g;
  for (const auto& v : mit.vertices()) {
    if (v.id < count) g.addVertex(v.id, v.pose);
  }
  for (const auto& e : mit.edges()) {
    const auto from = g.find(mit.vertex(e.from).id);
    const auto to = g.find(mit.vertex(e.to).id);
    if (from && to) g.addEdge(*from, *to, e.measurement, e.information, e.loop);
  }
  return g;
}

TEST(PoseGraph, CeresMatchesADenseGaussNewtonOnTheFirst240VerticesOfMit) {
  const std::string path = sharedG2o("MIT.g2o");
  SKIP_UNLESS_EXISTS(path);
  PoseGraph2D g = mitPrefix(metricmap::readG2o2D(path), 240);
  ASSERT_EQ(g.vertexCount(), 240u);
  std::size_t loops = 0;
  for (const auto& e : g.edges()) loops += e.loop ? 1 : 0;
  ASSERT_GE(loops, 5u);  // 58-29, 132-71, 155-96, 210-102, 224-165, 231-170, 9-4

  // The library's chi² (g2o's error) equals the oracle's through Isometry2d.
  std::vector<double> x0(3 * g.vertexCount());
  for (std::size_t i = 0; i < g.vertexCount(); ++i) {
    x0[3 * i] = g.vertex(i).pose.x;
    x0[3 * i + 1] = g.vertex(i).pose.y;
    x0[3 * i + 2] = g.vertex(i).pose.theta;
  }
  const double chi2_0 = oracleChi2(g, x0);
  EXPECT_NEAR(g.chi2(), chi2_0, 1e-12 * chi2_0);

  int gn_iterations = 0;
  const std::vector<double> xs = denseGaussNewton(g, &gn_iterations);
  const double gn_chi2 = oracleChi2(g, xs);

  PoseGraphOptimizeOptions options;
  options.loop_loss = RobustLoss::None;  // plain least squares, as the oracle
  options.max_iterations = 200;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  const auto result = metricmap::optimize(g, options);
  std::cout << "[ MIT 0..239 ] edges " << g.edgeCount() << ", loops " << loops << ": chi2 "
            << result.initial_chi2 << " -> " << result.final_chi2 << " in " << result.iterations
            << " iterations (" << result.linear_solver << "); dense Gauss-Newton " << gn_chi2
            << " in " << gn_iterations << " iterations\n";
  EXPECT_NE(result.termination, metricmap::PoseGraphTermination::Failure) << result.message;
  EXPECT_NEAR(result.initial_chi2, chi2_0, 1e-12 * chi2_0);
  // Ceres' cost is chi² / 2 without a robust loss.
  EXPECT_NEAR(2 * result.initial_cost, result.initial_chi2, 1e-9 * result.initial_chi2);
  EXPECT_NEAR(2 * result.final_cost, result.final_chi2, 1e-9 * result.final_chi2);
  EXPECT_LT(result.final_chi2, 0.5 * result.initial_chi2);
  // Both reach the same stationary point: chi² is flat there, so its values agree to far
  // better than the poses (the oracle's central differences shift its fixed point by O(h²)).
  EXPECT_NEAR(result.final_chi2, gn_chi2, 1e-8 * gn_chi2);
  double worst = 0.0;
  for (std::size_t i = 0; i < g.vertexCount(); ++i) {
    const Pose2D& p = g.vertex(i).pose;
    worst = std::max({worst, std::abs(p.x - xs[3 * i]), std::abs(p.y - xs[3 * i + 1]),
                      std::abs(std::remainder(p.theta - xs[3 * i + 2], 2 * kPi))});
  }
  std::cout << "[ MIT 0..239 ] largest pose difference Ceres vs Gauss-Newton: " << worst << "\n";
  // Metres and radians; the poses span about 100 m. The oracle's Jacobians by central
  // differences leave its iterates wandering by about 1e-6 along the graph's weakest direction
  // (it ends at its iteration cap, chi² flat to 1e-12), so the poses agree to a few 1e-6.
  EXPECT_LT(worst, 5e-6);
}

TEST(PoseGraph, RobustLossOnLoopEdgesResistsAWrongLoopClosure) {
  const std::string path = sharedG2o("MIT.g2o");
  SKIP_UNLESS_EXISTS(path);
  const PoseGraph2D clean = mitPrefix(metricmap::readG2o2D(path), 240);
  PoseGraphOptimizeOptions options;
  options.loop_loss = RobustLoss::None;
  PoseGraph2D reference = clean;
  metricmap::optimize(reference, options);

  // One wrong loop closure arrives in the optimised graph (as in incremental SLAM): vertex 200
  // "seen" 5 m beside vertex 20, and confident (σ = 0.1 m, 0.03 rad), as a false scan match is.
  const auto broken = [&] {
    PoseGraph2D g = reference;
    g.addEdge(20, 200, Pose2D{0.0, 5.0, 0.0}, Eigen::Vector3d(100, 100, 1000).asDiagonal(), true);
    return g;
  };
  const auto deviation = [&](const PoseGraph2D& g) {
    double worst = 0.0;
    for (std::size_t i = 0; i < g.vertexCount(); ++i) {
      worst = std::max(worst, std::hypot(g.vertex(i).pose.x - reference.vertex(i).pose.x,
                                         g.vertex(i).pose.y - reference.vertex(i).pose.y));
    }
    return worst;
  };
  PoseGraph2D plain = broken();
  metricmap::optimize(plain, options);
  PoseGraph2D robust = broken();
  options.loop_loss = RobustLoss::Cauchy;
  metricmap::optimize(robust, options);
  std::cout << "[ wrong loop ] largest position change: least squares " << deviation(plain)
            << " m, Cauchy on loop edges " << deviation(robust) << " m\n";
  EXPECT_GT(deviation(plain), 1.0);
  EXPECT_LT(deviation(robust), 0.5 * deviation(plain));
}

TEST(PoseGraph, RefusesBadOptionsAndEdges) {
  PoseGraph2D g;
  g.addVertex(0, Pose2D{});
  g.addVertex(7, Pose2D{1, 0, 0});
  EXPECT_TRUE(g.vertex(0).fixed);
  EXPECT_FALSE(g.vertex(1).fixed);
  EXPECT_THROW(g.addVertex(7, Pose2D{}), std::invalid_argument);
  EXPECT_THROW(g.addVertex(-1, Pose2D{}), std::invalid_argument);
  EXPECT_THROW(g.addVertex(8, Pose2D{NAN, 0, 0}), std::invalid_argument);
  EXPECT_THROW(g.addEdge(0, 0, Pose2D{}, Eigen::Matrix3d::Identity()), std::invalid_argument);
  EXPECT_THROW(g.addEdge(0, 2, Pose2D{}, Eigen::Matrix3d::Identity()), std::invalid_argument);
  EXPECT_THROW(g.addEdge(0, 1, Pose2D{}, -Eigen::Matrix3d::Identity()), std::invalid_argument);
  g.addEdge(0, 1, Pose2D{1, 0, 0}, Eigen::Matrix3d::Identity());
  PoseGraphOptimizeOptions options;
  options.threads = 0;
  EXPECT_THROW(metricmap::optimize(g, options), std::invalid_argument);
  options = {};
  options.max_iterations = 0;
  EXPECT_THROW(metricmap::optimize(g, options), std::invalid_argument);
  options = {};
  options.loss_scale = NAN;
  EXPECT_THROW(metricmap::optimize(g, options), std::invalid_argument);
  PoseGraph3D g3;
  Pose3D bad;
  bad.rotation = Eigen::Quaterniond(2, 0, 0, 0);
  EXPECT_THROW(g3.addVertex(0, bad), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// g2o files.

/// Data lines of a g2o file as tokens.
std::vector<std::vector<std::string>> tokenLines(const std::string& text) {
  std::vector<std::vector<std::string>> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::vector<std::string> tokens;
    for (std::string t; ls >> t;) tokens.push_back(t);
    if (!tokens.empty()) lines.push_back(tokens);
  }
  return lines;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The written text has the input's lines, tags and ids, and every number equal as a double.
void expectSameNumbers(const std::string& input, const std::string& written) {
  const auto a = tokenLines(input);
  const auto b = tokenLines(written);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].size(), b[i].size()) << "line " << i + 1;
    EXPECT_EQ(a[i][0], b[i][0]) << "line " << i + 1;
    for (std::size_t k = 1; k < a[i].size(); ++k) {
      ASSERT_EQ(std::strtod(a[i][k].c_str(), nullptr), std::strtod(b[i][k].c_str(), nullptr))
          << "line " << i + 1 << " value " << k << ": " << a[i][k] << " vs " << b[i][k];
    }
  }
}

template <typename Graph>
void expectIdenticalGraphs(const Graph& a, const Graph& b) {
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  ASSERT_EQ(a.edgeCount(), b.edgeCount());
  for (std::size_t i = 0; i < a.vertexCount(); ++i) {
    EXPECT_EQ(a.vertex(i).id, b.vertex(i).id);
    EXPECT_EQ(a.vertex(i).fixed, b.vertex(i).fixed);
    if constexpr (std::is_same_v<Graph, PoseGraph2D>) {
      EXPECT_EQ(a.vertex(i).pose.x, b.vertex(i).pose.x);
      EXPECT_EQ(a.vertex(i).pose.y, b.vertex(i).pose.y);
      EXPECT_EQ(a.vertex(i).pose.theta, b.vertex(i).pose.theta);
    } else {
      EXPECT_EQ(a.vertex(i).pose.translation, b.vertex(i).pose.translation);
      EXPECT_EQ(a.vertex(i).pose.rotation.coeffs(), b.vertex(i).pose.rotation.coeffs());
    }
  }
  for (std::size_t i = 0; i < a.edgeCount(); ++i) {
    const auto& ea = a.edge(i);
    const auto& eb = b.edge(i);
    EXPECT_EQ(ea.from, eb.from);
    EXPECT_EQ(ea.to, eb.to);
    EXPECT_EQ(ea.loop, eb.loop);
    EXPECT_EQ(ea.information, eb.information);
    if constexpr (std::is_same_v<Graph, PoseGraph2D>) {
      EXPECT_EQ(ea.measurement.x, eb.measurement.x);
      EXPECT_EQ(ea.measurement.y, eb.measurement.y);
      EXPECT_EQ(ea.measurement.theta, eb.measurement.theta);
    } else {
      EXPECT_EQ(ea.measurement.translation, eb.measurement.translation);
      EXPECT_EQ(ea.measurement.rotation.coeffs(), eb.measurement.rotation.coeffs());
    }
  }
}

TEST(G2oIo, RoundTrip2DKeepsEveryNumber) {
  const std::string path = sharedG2o("MIT.g2o");
  SKIP_UNLESS_EXISTS(path);
  const PoseGraph2D g = metricmap::readG2o2D(path);
  EXPECT_EQ(g.vertexCount(), 808u);
  EXPECT_EQ(g.edgeCount(), 827u);
  expectSameNumbers(slurp(path), metricmap::formatG2o(g));
  const std::string out = (scratchDir() / "mit_copy.g2o").string();
  metricmap::writeG2o(out, g);
  expectIdenticalGraphs(g, metricmap::readG2o2D(out));
  // An optimised graph (wrapped angles, new poses) round-trips too.
  PoseGraph2D optimised = metricmap::readG2o2D(path);
  metricmap::optimize(optimised);
  metricmap::writeG2o(out, optimised);
  expectIdenticalGraphs(optimised, metricmap::readG2o2D(out));
}

TEST(G2oIo, RoundTrip3DKeepsEveryNumber) {
  const std::string path = sharedG2o("sphere2500.g2o");
  SKIP_UNLESS_EXISTS(path);
  const PoseGraph3D g = metricmap::readG2o3D(path);
  EXPECT_EQ(g.vertexCount(), 2500u);
  EXPECT_EQ(g.edgeCount(), 4949u);
  expectSameNumbers(slurp(path), metricmap::formatG2o(g));
  const std::string out = (scratchDir() / "sphere_copy.g2o").string();
  metricmap::writeG2o(out, g);
  expectIdenticalGraphs(g, metricmap::readG2o3D(out));
}

TEST(G2oIo, FixLinesAreReadAndWritten) {
  const std::string path = writeScratch("fix.g2o",
                                        "VERTEX_SE2 10 0 0 0\nVERTEX_SE2 11 1 0 0\n"
                                        "VERTEX_SE2 12 2 0 0\n"
                                        "EDGE_SE2 10 11 1 0 0 1 0 0 1 0 1\n"
                                        "EDGE_SE2 11 12 1 0 0 1 0 0 1 0 1\n"
                                        "# a comment\n\nFIX 11 12\n");
  const G2oGraph read = metricmap::readG2o(path);
  EXPECT_EQ(read.fixed_lines, 1u);
  const PoseGraph2D& g = read.graph2d;
  EXPECT_FALSE(g.vertex(0).fixed);
  EXPECT_TRUE(g.vertex(1).fixed);
  EXPECT_TRUE(g.vertex(2).fixed);
  EXPECT_NE(metricmap::formatG2o(g).find("\nFIX 11 12\n"), std::string::npos);
  const std::string out = (scratchDir() / "fix_copy.g2o").string();
  metricmap::writeG2o(out, g);
  expectIdenticalGraphs(g, metricmap::readG2o2D(out));
}

TEST(G2oIo, ChainsOdometryWhenTheFileHasNoVertices) {
  const std::string path = sharedG2o("manhattan.g2o");
  SKIP_UNLESS_EXISTS(path);
  const G2oGraph read = metricmap::readG2o(path);
  ASSERT_EQ(read.dimension, 2);
  EXPECT_TRUE(read.chained_guess);
  const PoseGraph2D& g = read.graph2d;
  ASSERT_EQ(g.vertexCount(), 3500u);
  ASSERT_EQ(g.edgeCount(), 5453u);
  EXPECT_TRUE(g.vertex(0).fixed);
  // Chain the odometry edges here with Isometry2d and compare.
  std::vector<Eigen::Isometry2d> chain(g.vertexCount(), Eigen::Isometry2d::Identity());
  std::vector<bool> placed(g.vertexCount(), false);
  placed[0] = true;
  for (const auto& e : g.edges()) {
    if (g.vertex(e.to).id == g.vertex(e.from).id + 1 && !placed[e.to]) {
      ASSERT_TRUE(placed[e.from]) << "odometry out of order at " << e.to;
      chain[e.to] = chain[e.from] * iso(e.measurement.x, e.measurement.y, e.measurement.theta);
      placed[e.to] = true;
    }
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < g.vertexCount(); ++i) {
    ASSERT_TRUE(placed[i]);
    ASSERT_EQ(g.vertex(i).id, static_cast<std::int64_t>(i));
    worst = std::max(
        worst,
        (chain[i].translation() - Eigen::Vector2d(g.vertex(i).pose.x, g.vertex(i).pose.y)).norm());
  }
  EXPECT_LT(worst, 1e-9);  // 3500 compositions of rounding apart
  // Odometry edges hold exactly at the chained guess; loop edges are far off.
  double odometry_chi2 = 0.0;
  for (std::size_t i = 0; i < g.edgeCount(); ++i) {
    if (!g.edge(i).loop) odometry_chi2 += g.edgeChi2(i);
  }
  std::cout << "[ manhattan ] chained guess: chi2 " << g.chi2() << " (odometry edges "
            << odometry_chi2 << ")\n";
  EXPECT_LT(odometry_chi2, 1e-12);
  EXPECT_GT(g.chi2(), 1e5);
}

/// readG2o(text) throws an InputError whose message holds every piece.
void expectRefused(const std::string& name, const std::string& text,
                   const std::vector<std::string>& pieces) {
  const std::string path = writeScratch(name, text);
  try {
    metricmap::readG2o(path);
    ADD_FAILURE() << name << ": read without error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const auto& piece : pieces) {
      EXPECT_NE(message.find(piece), std::string::npos)
          << name << ": '" << piece << "' not in: " << message;
    }
  }
}

std::string repeat(const std::string& piece, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += piece;
  return out;
}

const std::string kV0 = "VERTEX_SE2 0 0 0 0\n";
const std::string kV1 = "VERTEX_SE2 1 1 0 0\n";
const std::string kE01 = "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n";

TEST(G2oIo, HostileInputIsOneErrorNamingFileAndLine) {
  expectRefused("number.g2o", kV0 + "VERTEX_SE2 1 1 abc 0\n", {"number.g2o: line 2", "'abc'"});
  expectRefused("nan.g2o", kV0 + kV1 + "EDGE_SE2 0 1 nan 0 0 1 0 0 1 0 1\n",
                {"nan.g2o: line 3", "'nan'"});
  expectRefused("inf.g2o", kV0 + "VERTEX_SE2 1 inf 0 0\n", {"inf.g2o: line 2", "'inf'"});
  expectRefused("hex.g2o", kV0 + "VERTEX_SE2 1 0x10 0 0\n", {"hex.g2o: line 2", "'0x10'"});
  expectRefused("overflow.g2o", kV0 + "VERTEX_SE2 1 1e999 0 0\n", {"overflow.g2o: line 2"});
  expectRefused("negative_definite.g2o", kV0 + kV1 + "EDGE_SE2 0 1 1 0 0 -1 0 0 1 0 1\n",
                {"negative_definite.g2o: line 3", "not positive definite"});
  expectRefused("singular.g2o", kV0 + kV1 + "EDGE_SE2 0 1 1 0 0 1 1 0 1 0 1\n",
                {"singular.g2o: line 3", "not positive definite"});
  expectRefused("zero_info_3d.g2o",
                "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 0 0 0 0 0 0 1\n"
                "EDGE_SE3:QUAT 0 1 1 0 0 0 0 0 1" +
                    repeat(" 0", 21) + "\n",
                {"zero_info_3d.g2o: line 3"});
  expectRefused("unknown_vertex.g2o", kV0 + kV1 + "EDGE_SE2 0 5 1 0 0 1 0 0 1 0 1\n",
                {"unknown_vertex.g2o: line 3", "vertex 5", "no VERTEX line"});
  expectRefused("duplicate.g2o", kV0 + kV1 + "VERTEX_SE2 0 3 3 3\n",
                {"duplicate.g2o: line 3", "vertex id 0 is defined twice (lines 1 and 3)"});
  expectRefused("mixed.g2o", kV0 + "VERTEX_SE3:QUAT 1 0 0 0 0 0 0 1\n",
                {"mixed.g2o: line 2", "3D tag in a 2D graph (line 1)"});
  expectRefused("unknown_tag.g2o", kV0 + "VERTEX_XY 1 0 0\n",
                {"unknown_tag.g2o: line 2", "unknown tag 'VERTEX_XY'"});
  expectRefused("unknown_tag_first.g2o", "PARAMS_SE3OFFSET 0 0 0 0 0 0 0 1\n" + kV0,
                {"unknown_tag_first.g2o: line 1", "unknown tag 'PARAMS_SE3OFFSET'"});
  expectRefused("count.g2o", kV0 + "VERTEX_SE2 1 0 0\n", {"count.g2o: line 2", "3 values, not 4"});
  expectRefused("edge_count.g2o", kV0 + kV1 + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0\n",
                {"edge_count.g2o: line 3", "10 values, not 11"});
  expectRefused("self.g2o", kV0 + kV1 + "EDGE_SE2 1 1 1 0 0 1 0 0 1 0 1\n",
                {"self.g2o: line 3", "to itself"});
  expectRefused("negative_id.g2o", kV0 + "VERTEX_SE2 -1 0 0 0\n", {"negative_id.g2o: line 2"});
  expectRefused("fraction_id.g2o", kV0 + "VERTEX_SE2 1.5 0 0 0\n", {"fraction_id.g2o: line 2"});
  expectRefused("huge_id.g2o", kV0 + "VERTEX_SE2 9223372036854775808 0 0 0\n",
                {"huge_id.g2o: line 2"});
  expectRefused("quaternion.g2o", "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 2\n",
                {"quaternion.g2o: line 1", "norm 2"});
  expectRefused("zero_quaternion.g2o", "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 0\n",
                {"zero_quaternion.g2o: line 1", "norm 0"});
  expectRefused("fix.g2o", kV0 + kV1 + kE01 + "FIX 4\n", {"fix.g2o: line 4", "FIX names vertex 4"});
  expectRefused("empty.g2o", "", {"empty.g2o: no VERTEX_SE2"});
  expectRefused("comments.g2o", "# nothing\nFIX 0\n", {"comments.g2o: no VERTEX_SE2"});
  // translations are bounded (1e6 m): the overflow comes from the information's scale
  expectRefused("chi2_overflow.g2o", kV0 + kV1 + "EDGE_SE2 0 1 1e6 0 0 1e300 0 0 1 0 1\n",
                {"chi2_overflow.g2o: line 3", "not finite"});
  expectRefused("huge_measurement.g2o", kV0 + kV1 + "EDGE_SE2 0 1 1e200 0 0 1 0 0 1 0 1\n",
                {"huge_measurement.g2o: line 3", "beyond 1000000 m"});
  EXPECT_THROW(metricmap::readG2o((scratchDir() / "absent.g2o").string()), InputError);
  EXPECT_THROW(metricmap::readG2o(scratchDir().string()), InputError);  // a directory
  // A 2D file where a 3D graph is needed, and the other way round.
  const std::string two = writeScratch("two.g2o", kV0 + kV1 + kE01);
  EXPECT_THROW(metricmap::readG2o3D(two), InputError);
  EXPECT_NO_THROW(metricmap::readG2o2D(two));
}

TEST(G2oIo, ABrokenOdometryChainNamesTheFirstMissingVertex) {
  // Vertex 2 appears in no edge.
  expectRefused("missing.g2o",
                "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE_SE2 1 3 1 0 0 1 0 0 1 0 1\n"
                "EDGE_SE2 3 4 1 0 0 1 0 0 1 0 1\n",
                {"missing.g2o: no VERTEX lines", "no edge names vertex 2"});
  // Every vertex is named, but nothing joins 1 to 2 (only a loop edge 0 -> 2).
  expectRefused(
      "broken.g2o",
      "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE_SE2 0 2 1 0 0 1 0 0 1 0 1\n"
      "EDGE_SE2 2 3 1 0 0 1 0 0 1 0 1\n",
      {"broken.g2o: no VERTEX lines", "no edge joins vertex 1 and vertex 2", "breaks at vertex 2"});
  // A huge id costs no memory: the ids are dense indices, the chain fails at once.
  expectRefused("huge_chain.g2o",
                "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n"
                "EDGE_SE2 1 9223372036854775807 1 0 0 1 0 0 1 0 1\n",
                {"no edge names vertex 2", "largest id is 9223372036854775807"});
  // A reversed odometry edge (k -> k-1) chains through its inverse.
  const std::string path = writeScratch("reversed.g2o",
                                        "EDGE_SE2 0 1 1 0 1.5707963267948966 1 0 0 1 0 1\n"
                                        "EDGE_SE2 2 1 -1 0 0 1 0 0 1 0 1\n");
  const PoseGraph2D g = metricmap::readG2o2D(path);
  ASSERT_EQ(g.vertexCount(), 3u);
  // x1 = (1, 0, π/2); x2 is 1 m ahead of x1 along its heading: (1, 1, π/2).
  EXPECT_NEAR(g.vertex(2).pose.x, 1.0, 1e-12);
  EXPECT_NEAR(g.vertex(2).pose.y, 1.0, 1e-12);
  EXPECT_NEAR(g.vertex(2).pose.theta, kPi / 2, 1e-12);
  EXPECT_NEAR(g.chi2(), 0.0, 1e-20);
}

TEST(G2oIo, HugeVertexIdsAreMappedToDenseIndices) {
  const std::string path =
      writeScratch("huge.g2o",
                   "VERTEX_SE2 9223372036854775807 0 0 0\nVERTEX_SE2 5000000000000 1 0 0\n"
                   "EDGE_SE2 9223372036854775807 5000000000000 1 0 0 1 0 0 1 0 1\n");
  const PoseGraph2D g = metricmap::readG2o2D(path);
  ASSERT_EQ(g.vertexCount(), 2u);
  EXPECT_EQ(g.edge(0).from, 0u);
  EXPECT_EQ(g.edge(0).to, 1u);
  EXPECT_TRUE(g.edge(0).loop);  // 5000000000000 is not 2^63 - 1 + 1
  expectSameNumbers(slurp(path), metricmap::formatG2o(g));
}

// ---------------------------------------------------------------------------------------------
// The real sets.

/// g2o's SE(3) chi² through Isometry3d: the oracle for the 3D error.
double isometryChi2(const PoseGraph3D& g) {
  const auto iso3 = [](const Pose3D& p) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translate(p.translation);
    t.rotate(p.rotation.normalized().toRotationMatrix());
    return t;
  };
  double sum = 0.0;
  for (const auto& e : g.edges()) {
    const Eigen::Isometry3d d = iso3(e.measurement).inverse() *
                                (iso3(g.vertex(e.from).pose).inverse() * iso3(g.vertex(e.to).pose));
    Eigen::Quaterniond q(d.rotation());
    if (q.w() < 0) q.coeffs() *= -1;
    Eigen::Matrix<double, 6, 1> r;
    r << d.translation(), q.vec();
    sum += r.dot(e.information * r);
  }
  return sum;
}

TEST(PoseGraph, LowersChi2OnMit) {
  const std::string path = sharedG2o("MIT.g2o");
  SKIP_UNLESS_EXISTS(path);
  PoseGraph2D g = metricmap::readG2o2D(path);
  PoseGraphOptimizeOptions options;
  options.loop_loss = RobustLoss::None;
  options.max_iterations = 1000;  // about 370 from MIT's initial poses
  const auto r = metricmap::optimize(g, options);
  std::cout << "[ MIT ] chi2 " << r.initial_chi2 << " -> " << r.final_chi2 << ", " << r.iterations
            << " iterations, " << metricmap::terminationName(r.termination) << ", " << r.seconds
            << " s\n";
  EXPECT_EQ(r.termination, metricmap::PoseGraphTermination::Converged) << r.message;
  EXPECT_LT(r.final_chi2, 0.01 * r.initial_chi2);
  EXPECT_NEAR(r.final_chi2, g.chi2(), 1e-9 * r.final_chi2);
}

TEST(PoseGraph, LowersChi2OnSphere2500) {
  const std::string path = sharedG2o("sphere2500.g2o");
  SKIP_UNLESS_EXISTS(path);
  PoseGraph3D g = metricmap::readG2o3D(path);
  const double oracle_0 = isometryChi2(g);
  EXPECT_NEAR(g.chi2(), oracle_0, 1e-9 * oracle_0);
  PoseGraphOptimizeOptions options;
  options.loop_loss = RobustLoss::None;
  options.threads = 2;
  const auto r = metricmap::optimize(g, options);
  std::cout << "[ sphere2500 ] chi2 " << r.initial_chi2 << " -> " << r.final_chi2 << ", "
            << r.iterations << " iterations, " << metricmap::terminationName(r.termination) << ", "
            << r.seconds << " s\n";
  EXPECT_EQ(r.termination, metricmap::PoseGraphTermination::Converged) << r.message;
  EXPECT_LT(r.final_chi2, 0.01 * r.initial_chi2);
  EXPECT_NEAR(2 * r.final_cost, r.final_chi2, 1e-6 * r.final_chi2);
  const double oracle = isometryChi2(g);
  EXPECT_NEAR(r.final_chi2, oracle, 1e-9 * oracle);
  for (const auto& v : g.vertices()) {
    EXPECT_NEAR(v.pose.rotation.norm(), 1.0, 1e-12);
  }
}

}  // namespace
