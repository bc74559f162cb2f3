#include "metricmap/posegraph/g2o_io.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/trajectory_text.h"

namespace metricmap {
namespace {

using detail::forEachDataLine;
using detail::lineNumber;
using detail::lineWhere;
using Tokens = std::vector<std::string_view>;

constexpr std::string_view kFix = "FIX";

/// 2 or 3 for the pose tags, 0 for FIX, -1 for any other tag.
int tagDimension(std::string_view tag) {
  if (tag == "VERTEX_SE2" || tag == "EDGE_SE2") return 2;
  if (tag == "VERTEX_SE3:QUAT" || tag == "EDGE_SE3:QUAT") return 3;
  if (tag == kFix) return 0;
  return -1;
}

template <typename Graph>
struct Traits;

template <>
struct Traits<PoseGraph2D> {
  static constexpr int kDimension = 2;
  static constexpr std::string_view kVertex = "VERTEX_SE2";
  static constexpr std::string_view kEdge = "EDGE_SE2";
  static constexpr const char* kPoseFields = "x y theta";
  static constexpr std::size_t kPoseValues = 3;
  static Pose2D pose(const double* v) { return {v[0], v[1], v[2]}; }
  template <typename Out>
  static void appendPose(Out&& out, const Pose2D& p) {
    out(p.x);
    out(p.y);
    out(p.theta);
  }
};

template <>
struct Traits<PoseGraph3D> {
  static constexpr int kDimension = 3;
  static constexpr std::string_view kVertex = "VERTEX_SE3:QUAT";
  static constexpr std::string_view kEdge = "EDGE_SE3:QUAT";
  static constexpr const char* kPoseFields = "x y z qx qy qz qw";
  static constexpr std::size_t kPoseValues = 7;
  static Pose3D pose(const double* v) {
    Pose3D p;
    p.translation = Eigen::Vector3d(v[0], v[1], v[2]);
    p.rotation = Eigen::Quaterniond(v[6], v[3], v[4], v[5]);  // (w, x, y, z)
    return p;
  }
  template <typename Out>
  static void appendPose(Out&& out, const Pose3D& p) {
    for (int i = 0; i < 3; ++i) out(p.translation[i]);
    out(p.rotation.x());
    out(p.rotation.y());
    out(p.rotation.z());
    out(p.rotation.w());
  }
};

/// An edge as read, before its ids are resolved to vertex indices.
template <typename Graph>
struct PendingEdge {
  std::size_t line = 0;
  std::int64_t from = 0;
  std::int64_t to = 0;
  typename Graph::Pose measurement;
  typename Graph::Information information;
};

/// Runs fn(); a std::invalid_argument from it (the graph's checks) becomes an InputError
/// "PATH: line N: REASON".
template <typename Fn>
auto atLine(const std::string& path, std::size_t line, Fn&& fn) {
  try {
    return fn();
  } catch (const std::invalid_argument& e) {
    throw InputError(lineWhere(path, line) + ": " + e.what());
  }
}

std::int64_t parseId(std::string_view token, const std::string& path, std::size_t line) {
  try {
    return parseInteger(token, lineWhere(path, line) + ": vertex id", 0,
                        std::numeric_limits<std::int64_t>::max());
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

void requireTokens(const Tokens& tokens, std::size_t count, const std::string& fields,
                   const std::string& path, std::size_t line) {
  if (tokens.size() != count) {
    throw InputError(lineWhere(path, line) + ": " + std::string(tokens[0]) + " has " +
                     std::to_string(tokens.size() - 1) + " values, not " +
                     std::to_string(count - 1) + " (" + fields + ")");
  }
}

/// The dimension of the first pose tag in the file and its line. \throws InputError if none
std::pair<int, std::size_t> fileDimension(const std::string& text, const std::string& path) {
  int dimension = 0;
  std::size_t first = 0;
  forEachDataLine(text, [&](std::size_t n, const Tokens& tokens) {
    if (dimension > 0) return;
    const int d = tagDimension(tokens[0]);
    if (d > 0) {
      dimension = d;
      first = n;
    } else if (d < 0) {
      throw InputError(lineWhere(path, n) + ": unknown tag '" + quoteForMessage(tokens[0]) +
                       "' (this reader takes VERTEX_SE2, EDGE_SE2, VERTEX_SE3:QUAT, "
                       "EDGE_SE3:QUAT and FIX)");
    }
  });
  if (dimension == 0) {
    throw InputError(path + ": no VERTEX_SE2, EDGE_SE2, VERTEX_SE3:QUAT or EDGE_SE3:QUAT line");
  }
  return {dimension, first};
}

/// The chained initial guess of a file without VERTEX lines (see g2o_io.h).
template <typename Graph>
void chainVertices(const std::vector<PendingEdge<Graph>>& edges, const std::string& path,
                   Graph& graph) {
  std::vector<std::int64_t> ids;
  ids.reserve(2 * edges.size());
  for (const auto& e : edges) {
    ids.push_back(e.from);
    ids.push_back(e.to);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const std::string context = path + ": no VERTEX lines, so the initial guess chains the " +
                              "odometry edges (k-1, k) from vertex 0";
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (ids[k] != static_cast<std::int64_t>(k)) {
      throw InputError(context + ", but no edge names vertex " + std::to_string(k) +
                       " (the edges name " + std::to_string(ids.size()) +
                       " vertices, the largest id is " + std::to_string(ids.back()) + ")");
    }
  }
  const std::size_t n = ids.size();
  const std::size_t none = edges.size();
  std::vector<std::size_t> forward(n, none);   // first edge k-1 -> k
  std::vector<std::size_t> backward(n, none);  // first edge k -> k-1
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto& e = edges[i];
    if (e.to - e.from == 1 && forward[e.to] == none) forward[e.to] = i;
    if (e.from - e.to == 1 && backward[e.from] == none) backward[e.from] = i;
  }
  typename Graph::Pose pose;
  graph.addVertex(0, pose);
  for (std::size_t k = 1; k < n; ++k) {
    if (forward[k] != none) {
      pose = compose(pose, edges[forward[k]].measurement);
    } else if (backward[k] != none) {
      pose = compose(pose, inverse(edges[backward[k]].measurement));
    } else {
      throw InputError(context + ", but no edge joins vertex " + std::to_string(k - 1) +
                       " and vertex " + std::to_string(k) + ": the chain breaks at vertex " +
                       std::to_string(k));
    }
    atLine(path, edges[forward[k] != none ? forward[k] : backward[k]].line,
           [&] { return graph.addVertex(static_cast<std::int64_t>(k), pose); });
  }
}

/// One EDGE line: ids, measurement and information (the upper triangle, row by row).
template <typename Graph>
PendingEdge<Graph> parseEdge(const Tokens& tokens, const std::string& path, std::size_t n) {
  using T = Traits<Graph>;
  constexpr std::size_t kInfoValues = Graph::kDim * (Graph::kDim + 1) / 2;
  const std::string edge_fields = "i j " + std::string(T::kPoseFields) + " and the " +
                                  std::to_string(kInfoValues) +
                                  " upper-triangle entries of the information matrix";
  double values[T::kPoseValues + kInfoValues];
  requireTokens(tokens, 3 + T::kPoseValues + kInfoValues, edge_fields, path, n);
  PendingEdge<Graph> e;
  e.line = n;
  e.from = parseId(tokens[1], path, n);
  e.to = parseId(tokens[2], path, n);
  for (std::size_t i = 0; i < T::kPoseValues + kInfoValues; ++i) {
    values[i] = lineNumber(tokens[3 + i], path, n);
  }
  e.measurement = T::pose(values);
  const double* upper = values + T::kPoseValues;
  for (int r = 0; r < Graph::kDim; ++r) {
    for (int c = r; c < Graph::kDim; ++c) {
      e.information(r, c) = e.information(c, r) = *upper++;
    }
  }
  atLine(path, n, [&] {
    Graph::validatePose(e.measurement);
    Graph::validateInformation(e.information);
    return 0;
  });
  return e;
}

/// The edges (between vertices the graph has, with a finite chi² at the initial poses) and the
/// FIX lines (only the vertices they name are fixed then).
template <typename Graph>
void addEdgesAndFixes(const std::vector<PendingEdge<Graph>>& edges,
                      const std::vector<std::pair<std::size_t, std::int64_t>>& fixes,
                      const std::string& path, Graph& graph) {
  for (const auto& e : edges) {
    const auto from = graph.find(e.from);
    const auto to = graph.find(e.to);
    if (!from || !to) {
      throw InputError(lineWhere(path, e.line) + ": the edge names vertex " +
                       std::to_string(from ? e.to : e.from) + ", which no VERTEX line defines");
    }
    atLine(path, e.line, [&] {
      return graph.addEdge(*from, *to, e.measurement, e.information, e.to - e.from != 1);
    });
  }
  for (std::size_t i = 0; i < graph.edgeCount(); ++i) {
    if (!std::isfinite(graph.edgeChi2(i))) {
      throw InputError(lineWhere(path, edges[i].line) +
                       ": the edge's chi² at the initial poses is not finite (values too large)");
    }
  }
  if (fixes.empty()) return;
  for (std::size_t i = 0; i < graph.vertexCount(); ++i) graph.setFixed(i, false);
  for (const auto& [line, id] : fixes) {
    const auto index = graph.find(id);
    if (!index) {
      throw InputError(lineWhere(path, line) + ": FIX names vertex " + std::to_string(id) +
                       ", which the graph does not have");
    }
    graph.setFixed(*index, true);
  }
}

template <typename Graph>
void parseGraph(const std::string& text, const std::string& path, std::size_t first_line,
                G2oGraph& out, Graph& graph) {
  using T = Traits<Graph>;
  const std::string vertex_fields = "id " + std::string(T::kPoseFields);
  std::vector<std::size_t> vertex_lines;
  std::vector<PendingEdge<Graph>> edges;
  std::vector<std::pair<std::size_t, std::int64_t>> fixes;  // (line, id)
  double values[T::kPoseValues];

  forEachDataLine(text, [&](std::size_t n, const Tokens& tokens) {
    const std::string_view tag = tokens[0];
    const int dimension = tagDimension(tag);
    if (dimension < 0) {
      throw InputError(lineWhere(path, n) + ": unknown tag '" + quoteForMessage(tag) +
                       "' (this reader takes VERTEX_SE2, EDGE_SE2, VERTEX_SE3:QUAT, "
                       "EDGE_SE3:QUAT and FIX)");
    }
    if (dimension > 0 && dimension != T::kDimension) {
      throw InputError(lineWhere(path, n) + ": " + std::string(tag) + " is a " +
                       std::to_string(dimension) + "D tag in a " + std::to_string(T::kDimension) +
                       "D graph (line " + std::to_string(first_line) +
                       "): one file holds one kind of graph");
    }
    if (tag == kFix) {
      if (tokens.size() < 2) throw InputError(lineWhere(path, n) + ": FIX names no vertex");
      for (std::size_t i = 1; i < tokens.size(); ++i) {
        fixes.emplace_back(n, parseId(tokens[i], path, n));
      }
      ++out.fixed_lines;
    } else if (tag == T::kVertex) {
      requireTokens(tokens, 2 + T::kPoseValues, vertex_fields, path, n);
      const std::int64_t id = parseId(tokens[1], path, n);
      for (std::size_t i = 0; i < T::kPoseValues; ++i) {
        values[i] = lineNumber(tokens[2 + i], path, n);
      }
      if (const auto previous = graph.find(id)) {
        throw InputError(lineWhere(path, n) + ": vertex id " + std::to_string(id) +
                         " is defined twice (lines " + std::to_string(vertex_lines[*previous]) +
                         " and " + std::to_string(n) + ")");
      }
      atLine(path, n, [&] { return graph.addVertex(id, T::pose(values)); });
      vertex_lines.push_back(n);
    } else {
      edges.push_back(parseEdge<Graph>(tokens, path, n));
    }
  });

  out.chained_guess = graph.vertexCount() == 0;
  if (out.chained_guess) chainVertices(edges, path, graph);
  addEdgesAndFixes(edges, fixes, path, graph);
}

/// Appends " VALUE", the shortest decimal text that reads back as the same double.
struct NumberAppender {
  std::string& out;
  void operator()(double value) const {
    char buf[40];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    out.push_back(' ');
    out.append(buf, result.ptr);
  }
};

template <typename Graph>
std::string format(const Graph& graph) {
  using T = Traits<Graph>;
  std::string out;
  out.reserve(graph.vertexCount() * 64 + graph.edgeCount() * (Graph::kDim == 3 ? 160 : 400));
  const NumberAppender number{out};
  for (const auto& v : graph.vertices()) {
    out.append(T::kVertex);
    out.append(" " + std::to_string(v.id));
    T::appendPose(number, v.pose);
    out.push_back('\n');
  }
  for (const auto& e : graph.edges()) {
    out.append(T::kEdge);
    out.append(" " + std::to_string(graph.vertex(e.from).id) + " " +
               std::to_string(graph.vertex(e.to).id));
    T::appendPose(number, e.measurement);
    for (int r = 0; r < Graph::kDim; ++r) {
      for (int c = r; c < Graph::kDim; ++c) number(e.information(r, c));
    }
    out.push_back('\n');
  }
  std::size_t fixed = 0;
  bool first_alone = graph.vertexCount() > 0 && graph.vertex(0).fixed;
  for (std::size_t i = 0; i < graph.vertexCount(); ++i) {
    if (!graph.vertex(i).fixed) continue;
    ++fixed;
    if (i > 0) first_alone = false;
  }
  if (fixed > 0 && !first_alone) {
    out.append(kFix);
    for (const auto& v : graph.vertices()) {
      if (v.fixed) out.append(" " + std::to_string(v.id));
    }
    out.push_back('\n');
  }
  return out;
}

}  // namespace

G2oGraph readG2o(const std::string& path) {
  // The shortest line that adds a value: "VERTEX_SE2 0 0 0 0\n" (19 bytes); an SE(3) edge of
  // at least 74 bytes stores about 800 (read, then in the graph).
  const std::string text = detail::readBoundedText(path, 74, 2 * sizeof(PoseGraph3D::Edge) + 64);
  const auto [dimension, first_line] = fileDimension(text, path);
  G2oGraph out;
  out.dimension = dimension;
  if (dimension == 2) {
    parseGraph(text, path, first_line, out, out.graph2d);
  } else {
    parseGraph(text, path, first_line, out, out.graph3d);
  }
  return out;
}

PoseGraph2D readG2o2D(const std::string& path) {
  G2oGraph g = readG2o(path);
  if (g.dimension != 2) {
    throw InputError(path + ": holds a 3D graph (SE3:QUAT tags), a 2D graph (SE2) is needed");
  }
  return std::move(g.graph2d);
}

PoseGraph3D readG2o3D(const std::string& path) {
  G2oGraph g = readG2o(path);
  if (g.dimension != 3) {
    throw InputError(path + ": holds a 2D graph (SE2 tags), a 3D graph (SE3:QUAT) is needed");
  }
  return std::move(g.graph3d);
}

std::string formatG2o(const PoseGraph2D& graph) { return format(graph); }
std::string formatG2o(const PoseGraph3D& graph) { return format(graph); }

void writeG2o(const std::string& path, const PoseGraph2D& graph) {
  writeTextAtomic(path, formatG2o(graph));
}

void writeG2o(const std::string& path, const PoseGraph3D& graph) {
  writeTextAtomic(path, formatG2o(graph));
}

}  // namespace metricmap
