#pragma once
/// \file g2o_io.h
/// \brief g2o pose-graph files: VERTEX_SE2, EDGE_SE2, VERTEX_SE3:QUAT, EDGE_SE3:QUAT and FIX.
///
/// Lines (blanks separate tokens; blank lines and lines starting with '#' are skipped):
///   VERTEX_SE2 id x y theta
///   EDGE_SE2 i j dx dy dtheta I11 I12 I13 I22 I23 I33
///   VERTEX_SE3:QUAT id x y z qx qy qz qw
///   EDGE_SE3:QUAT i j dx dy dz dqx dqy dqz dqw I11 I12 .. I16 I22 .. I66 (21 values)
///   FIX id [id ...]
/// The information matrix is given by its upper triangle, row by row, translation first. An
/// edge i j measures x_i⁻¹ x_j; it is a loop edge (PoseGraph::Edge::loop, which the optimiser may
/// give a robust loss) unless j = i + 1.
///
/// Files without VERTEX lines get an initial guess by chaining odometry: the vertices are the
/// ids the edges name, which must be 0, 1, ..., n-1; vertex 0 is at the origin and vertex k at
/// x_{k-1} z, z the first edge k-1 -> k in the file (or the inverse of the first edge k -> k-1).
/// A vertex no edge names, or a k without such an edge, is an error naming that vertex (the
/// first one in id order).
///
/// The reader keeps the project's rules for hostile input: one InputError naming the file and
/// line for a bad token count or number (not a finite decimal: NaN and inf are refused), an id
/// that is not an integer in 0 .. 2^63-1, a non-unit quaternion (tolerance 1e-2), an information
/// matrix that is not positive definite, an edge naming a vertex no VERTEX line defines or
/// joining a vertex to itself, a vertex id defined twice, a FIX naming an unknown vertex, 2D and
/// 3D tags in one file, and any other tag (g2o's landmark, parameter and other vertex types are
/// refused, not skipped: a graph read without them would be another problem). Ids are mapped to
/// dense indices, so memory follows the file's size (bounded by the memory budget before it is
/// read), never an id's value. Values are kept as written (angles not wrapped, quaternions not
/// renormalised), so that writing a graph read from a file gives the same numbers.

#include <string>

#include "metricmap/posegraph/pose_graph.h"

namespace metricmap {

/// \brief What a g2o file holds: a 2D or a 3D graph.
struct G2oGraph {
  int dimension = 2;            ///< 2: the SE(2) tags (graph2d); 3: SE(3) (graph3d)
  PoseGraph2D graph2d;          ///< the graph when dimension is 2
  PoseGraph3D graph3d;          ///< the graph when dimension is 3
  bool chained_guess = false;   ///< no VERTEX lines: poses chained from the odometry edges
  std::size_t fixed_lines = 0;  ///< FIX lines read (none: the first vertex is fixed)
};

/// \brief Read a g2o file (2D or 3D, see the file comment).
/// \throws InputError naming the file (and line); CapacityError when the file does not fit the
/// memory budget
G2oGraph readG2o(const std::string& path);

/// \brief readG2o for a file that must hold a 2D graph. \throws InputError also for a 3D file
PoseGraph2D readG2o2D(const std::string& path);
/// \brief readG2o for a file that must hold a 3D graph. \throws InputError also for a 2D file
PoseGraph3D readG2o3D(const std::string& path);

/// \brief The graph as g2o text: VERTEX lines in index order, EDGE lines in edge order, then
/// one FIX line when the fixed vertices are other than the first vertex alone. Numbers are the
/// shortest decimal text that reads back as the same double, so a round trip is exact.
std::string formatG2o(const PoseGraph2D& graph);
/// \copydoc formatG2o(const PoseGraph2D&)
std::string formatG2o(const PoseGraph3D& graph);

/// \brief formatG2o, written through a temporary file and a rename (nothing is left at `path`
/// unless the whole file was written). \throws std::runtime_error naming the file
void writeG2o(const std::string& path, const PoseGraph2D& graph);
/// \copydoc writeG2o(const std::string&, const PoseGraph2D&)
void writeG2o(const std::string& path, const PoseGraph3D& graph);

}  // namespace metricmap
