// metricmap.PoseGraph / read_g2o: SE(2) and SE(3) pose graphs, g2o files and the Ceres
// optimiser (posegraph/).
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.h"
#include "metricmap/exceptions.h"
#include "metricmap/posegraph/g2o_io.h"
#include "metricmap/posegraph/optimize.h"
#include "object_lock.h"
#include "posegraph.h"
#include "posegraph_state.h"

namespace metricmap::python {

namespace {

/// (N, 3) x, y, theta or (N, 7) x, y, z, qx, qy, qz, qw.
py::array_t<double> vertexPoses(const PyPoseGraph& g) {
  if (g.dimension == 2) {
    const auto& v = g.graph2d.vertices();
    py::array_t<double> a({py::ssize_t(v.size()), py::ssize_t(3)});
    double* d = a.mutable_data();
    for (std::size_t k = 0; k < v.size(); ++k) {
      d[3 * k] = v[k].pose.x;
      d[3 * k + 1] = v[k].pose.y;
      d[3 * k + 2] = v[k].pose.theta;
    }
    return a;
  }
  const auto& v = g.graph3d.vertices();
  py::array_t<double> a({py::ssize_t(v.size()), py::ssize_t(7)});
  double* d = a.mutable_data();
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Pose3D& p = v[k].pose;
    const double row[7] = {p.translation.x(), p.translation.y(), p.translation.z(), p.rotation.x(),
                           p.rotation.y(),    p.rotation.z(),    p.rotation.w()};
    std::copy(row, row + 7, d + 7 * k);
  }
  return a;
}

template <typename Graph>
py::dict edgeArrays(const Graph& graph, int pose_size) {
  const auto& e = graph.edges();
  constexpr int D = Graph::kDim;
  const py::ssize_t n = static_cast<py::ssize_t>(e.size());
  py::array_t<long long> ends({n, py::ssize_t(2)});
  py::array_t<bool> loop(n);
  py::array_t<double> meas({n, py::ssize_t(pose_size)});
  py::array_t<double> info({n, py::ssize_t(D), py::ssize_t(D)});
  py::array_t<double> chi2(n);
  for (std::size_t k = 0; k < e.size(); ++k) {
    ends.mutable_data()[2 * k] = static_cast<long long>(e[k].from);
    ends.mutable_data()[2 * k + 1] = static_cast<long long>(e[k].to);
    loop.mutable_data()[k] = e[k].loop;
    double* m = meas.mutable_data() + pose_size * k;
    if constexpr (D == 3) {
      m[0] = e[k].measurement.x;
      m[1] = e[k].measurement.y;
      m[2] = e[k].measurement.theta;
    } else {
      const Pose3D& p = e[k].measurement;
      const double row[7] = {p.translation.x(), p.translation.y(), p.translation.z(),
                             p.rotation.x(),    p.rotation.y(),    p.rotation.z(),
                             p.rotation.w()};
      std::copy(row, row + 7, m);
    }
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) info.mutable_data()[(k * D + i) * D + j] = e[k].information(i, j);
    chi2.mutable_data()[k] = graph.edgeChi2(k);
  }
  py::dict d;
  d["ends"] = ends;
  d["loop"] = loop;
  d["measurements"] = meas;
  d["information"] = info;
  d["chi2"] = chi2;
  return d;
}

RobustLoss lossFrom(const std::string& name) { return parseRobustLoss(name); }

Pose2D pose2From(const py::handle& obj, const char* name) {
  auto a = doublesFromArray(obj, name);
  if (a.size() != 3 || a.ndim() != 1)
    throw py::value_error(std::string(name) + " must be (x, y, theta) for a 2D graph");
  return {a.data()[0], a.data()[1], a.data()[2]};
}

Pose3D pose3From(const py::handle& obj, const char* name) {
  auto a = doublesFromArray(obj, name);
  if (a.size() != 7 || a.ndim() != 1)
    throw py::value_error(std::string(name) + " must be (x, y, z, qx, qy, qz, qw) for a 3D graph");
  const double* d = a.data();
  Pose3D p;
  p.translation = Eigen::Vector3d(d[0], d[1], d[2]);
  p.rotation = Eigen::Quaterniond(d[6], d[3], d[4], d[5]);
  return p;
}

template <int D>
Eigen::Matrix<double, D, D> informationFrom(const py::handle& obj) {
  auto a = doublesFromArray(obj, "information");
  if (a.ndim() != 2 || a.shape(0) != D || a.shape(1) != D)
    throw py::value_error("information must have shape (" + std::to_string(D) + ", " +
                          std::to_string(D) + ")");
  Eigen::Matrix<double, D, D> m;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) m(i, j) = a.data()[i * D + j];
  return m;
}

}  // namespace

void initPoseGraph(py::module_& m) {
  py::class_<PyPoseGraph>(m, "PoseGraph", R"doc(
A pose graph in SE(2) (poses x, y, theta; 3x3 information) or SE(3) (poses x, y, z, qx, qy,
qz, qw; 6x6 information over translation and quaternion vector part), g2o's model and chi².
An edge i -> j measures x_i⁻¹ x_j. Read with :func:`read_g2o`, or build with
``PoseGraph(dimension)``, :meth:`add_vertex`, :meth:`add_edge`.
)doc")
      .def(py::init([](int dimension) {
             if (dimension != 2 && dimension != 3)
               throw py::value_error("dimension must be 2 or 3, got " + std::to_string(dimension));
             PyPoseGraph g;
             g.dimension = dimension;
             return g;
           }),
           py::arg("dimension") = 2)
      .def(py::pickle(
          [](const PyPoseGraph& g) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            return py::make_tuple(
                g.dimension, g.chained_guess,
                g.dimension == 2 ? poseGraphState(g.graph2d) : poseGraphState(g.graph3d));
          },
          [](const py::tuple& t) {
            if (t.size() != 3) throw py::value_error("PoseGraph: not a pickled pose graph");
            PyPoseGraph g;
            g.dimension = t[0].cast<int>();
            g.chained_guess = t[1].cast<bool>();
            if (g.dimension == 2)
              g.graph2d = poseGraphFrom<Pose2D, 3>(t[2].cast<py::tuple>(), "PoseGraph");
            else if (g.dimension == 3)
              g.graph3d = poseGraphFrom<Pose3D, 6>(t[2].cast<py::tuple>(), "PoseGraph");
            else
              throw py::value_error("PoseGraph: not a pickled pose graph");
            return g;
          }))
      .def(
          "__eq__",
          [](const PyPoseGraph& a, const py::object& other) {
            if (!py::isinstance<PyPoseGraph>(other)) return false;
            const auto& b = other.cast<const PyPoseGraph&>();
            if (&a == &b) return true;
            ObjectGuard ga(a.mutex, "PoseGraph"), gb(b.mutex, "PoseGraph");
            return a.dimension == b.dimension && a.chained_guess == b.chained_guess &&
                   samePoseGraph(a.graph2d, b.graph2d) && samePoseGraph(a.graph3d, b.graph3d);
          },
          py::is_operator())
      .def("__repr__",
           [](const PyPoseGraph& g) {
             ObjectGuard guard(g.mutex, "PoseGraph");
             const std::size_t v =
                 g.dimension == 2 ? g.graph2d.vertices().size() : g.graph3d.vertices().size();
             const std::size_t e =
                 g.dimension == 2 ? g.graph2d.edges().size() : g.graph3d.edges().size();
             std::size_t loops = 0;
             if (g.dimension == 2)
               for (const auto& x : g.graph2d.edges()) loops += x.loop;
             else
               for (const auto& x : g.graph3d.edges()) loops += x.loop;
             return "<metricmap.PoseGraph " + std::to_string(g.dimension) + "D, " +
                    std::to_string(v) + " vertices, " + std::to_string(e) + " edges (" +
                    std::to_string(loops) + " loops)>";
           })
      .def_readonly("dimension", &PyPoseGraph::dimension, "int: 2 or 3.")
      .def_readonly("chained_guess", &PyPoseGraph::chained_guess,
                    "bool: read from a file without VERTEX lines (poses chained from odometry).")
      .def(
          "add_vertex",
          [](PyPoseGraph& g, long long id, ArrayLike pose) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            return g.dimension == 2 ? g.graph2d.addVertex(id, pose2From(pose, "pose"))
                                    : g.graph3d.addVertex(id, pose3From(pose, "pose"));
          },
          py::arg("id"), py::arg("pose"),
          "Add a vertex (the first one added is fixed); returns its index. pose: (3,) x, y, "
          "theta (m, rad) or (7,) x, y, z, qx, qy, qz, qw. ValueError for a duplicate id or a "
          "non-finite pose.")
      .def(
          "add_edge",
          [](PyPoseGraph& g, std::size_t from, std::size_t to, ArrayLike measurement,
             ArrayLike information, bool loop) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            return g.dimension == 2
                       ? g.graph2d.addEdge(from, to, pose2From(measurement, "measurement"),
                                           informationFrom<3>(information), loop)
                       : g.graph3d.addEdge(from, to, pose3From(measurement, "measurement"),
                                           informationFrom<6>(information), loop);
          },
          py::arg("from_index"), py::arg("to_index"), py::arg("measurement"),
          py::arg("information"), py::arg("loop") = false,
          "Add an edge between vertex indices (measurement x_from⁻¹ x_to; information (3, 3) "
          "or (6, 6) symmetric positive definite); returns its index.")
      .def("__len__",
           [](const PyPoseGraph& g) {
             ObjectGuard guard(g.mutex, "PoseGraph");
             return g.dimension == 2 ? g.graph2d.vertexCount() : g.graph3d.vertexCount();
           })
      .def_property_readonly(
          "edge_count",
          [](const PyPoseGraph& g) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            return g.dimension == 2 ? g.graph2d.edgeCount() : g.graph3d.edgeCount();
          },
          "int: number of edges.")
      .def_property_readonly("poses", &vertexPoses,
                             "(N, 3) float64 x, y, theta (2D) or (N, 7) x, y, z, qx, qy, qz, qw "
                             "(3D): the vertices' poses, m and rad.")
      .def_property_readonly(
          "ids",
          [](const PyPoseGraph& g) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            std::vector<long long> ids;
            if (g.dimension == 2) {
              for (const auto& v : g.graph2d.vertices()) ids.push_back(v.id);
            } else {
              for (const auto& v : g.graph3d.vertices()) ids.push_back(v.id);
            }
            return arrayFrom(ids, {py::ssize_t(ids.size())});
          },
          "(N,) int64: the vertices' ids.")
      .def_property_readonly(
          "fixed",
          [](const PyPoseGraph& g) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            const std::size_t n =
                g.dimension == 2 ? g.graph2d.vertexCount() : g.graph3d.vertexCount();
            py::array_t<bool> a(static_cast<py::ssize_t>(n));
            for (std::size_t k = 0; k < n; ++k)
              a.mutable_data()[k] =
                  g.dimension == 2 ? g.graph2d.vertex(k).fixed : g.graph3d.vertex(k).fixed;
            return a;
          },
          "(N,) bool: vertices held constant.")
      .def(
          "edges",
          [](const PyPoseGraph& g) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            return g.dimension == 2 ? edgeArrays(g.graph2d, 3) : edgeArrays(g.graph3d, 7);
          },
          R"doc(
The edges as arrays: dict with ends (E, 2) int64 vertex indices, loop (E,) bool,
measurements (E, 3) or (E, 7), information (E, 3, 3) or (E, 6, 6), chi2 (E,) at the current
poses.
)doc")
      .def(
          "chi2",
          [](const PyPoseGraph& g) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            return g.dimension == 2 ? g.graph2d.chi2() : g.graph3d.chi2();
          },
          "float: Σ eᵀ Ω e over the edges at the current poses (g2o's chi²).")
      .def(
          "optimize",
          [](PyPoseGraph& g, int max_iterations, int threads, const std::string& odometry_loss,
             const std::string& loop_loss, double loss_scale) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            PoseGraphOptimizeOptions o;
            o.max_iterations = max_iterations;
            o.threads = threads;
            o.odometry_loss = lossFrom(odometry_loss);
            o.loop_loss = lossFrom(loop_loss);
            o.loss_scale = loss_scale;
            PoseGraphOptimizeResult r;
            {
              py::gil_scoped_release release;
              r = g.dimension == 2 ? optimize(g.graph2d, o) : optimize(g.graph3d, o);
            }
            py::dict d;
            d["initial_chi2"] = r.initial_chi2;
            d["final_chi2"] = r.final_chi2;
            d["initial_cost"] = r.initial_cost;
            d["final_cost"] = r.final_cost;
            d["iterations"] = r.iterations;
            d["termination"] = terminationName(r.termination);
            d["seconds"] = r.seconds;
            d["linear_solver"] = r.linear_solver;
            d["message"] = r.message;
            return d;
          },
          py::arg("max_iterations") = 100, py::arg("threads") = 1,
          py::arg("odometry_loss") = "none", py::arg("loop_loss") = "huber",
          py::arg("loss_scale") = 0.0, R"doc(
Optimise the non-fixed poses in place with Ceres (Levenberg-Marquardt), as `metricmap
posegraph` (whose --max-iterations defaults to 1000).

Parameters
----------
max_iterations : int
    >= 1.
threads : int
    Ceres' threads, >= 1.
odometry_loss, loop_loss : {'none', 'huber', 'cauchy'}
    Robust loss of edges i -> i+1 / of the other (loop) edges.
loss_scale : float
    In units of √chi² of one edge; 0: the 99 % point of chi² for the edge's dimension.

Returns
-------
dict
    initial_chi2, final_chi2, initial_cost, final_cost, iterations, termination
    ('converged', 'no_convergence', 'failure'), seconds, linear_solver, message.

Raises
------
ValueError
    options out of range. CapacityError: the solver does not fit the memory budget.
)doc")
      .def(
          "to_g2o",
          [](const PyPoseGraph& g) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            return g.dimension == 2 ? formatG2o(g.graph2d) : formatG2o(g.graph3d);
          },
          "str: the graph as g2o text (numbers that read back exactly).")
      .def(
          "write",
          [](const PyPoseGraph& g, const std::filesystem::path& path) {
            ObjectGuard guard(g.mutex, "PoseGraph");
            try {
              py::gil_scoped_release release;
              if (g.dimension == 2) {
                writeG2o(path.string(), g.graph2d);
              } else {
                writeG2o(path.string(), g.graph3d);
              }
            } catch (const std::runtime_error& e) {
              raiseOSError(e);
            }
          },
          py::arg("path"), "Write the graph as a g2o file (atomically). OSError when it fails.");

  m.def(
      "read_g2o",
      [](const std::filesystem::path& path) {
        G2oGraph g;
        {
          py::gil_scoped_release release;
          g = readG2o(path.string());
        }
        PyPoseGraph out;
        out.dimension = g.dimension;
        out.graph2d = std::move(g.graph2d);
        out.graph3d = std::move(g.graph3d);
        out.chained_guess = g.chained_guess;
        return out;
      },
      py::arg("path"), R"doc(
Read a g2o pose graph (VERTEX_SE2 / EDGE_SE2 or VERTEX_SE3:QUAT / EDGE_SE3:QUAT, FIX).

Returns
-------
PoseGraph

Raises
------
InputError
    a missing or malformed file (named with its line).
)doc");
}

}  // namespace metricmap::python
