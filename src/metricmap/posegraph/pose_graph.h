#pragma once
/// \file pose_graph.h
/// \brief Pose graphs in SE(2) and SE(3): vertices (poses with an id and a fixed flag) and
/// relative-pose edges with information matrices, g2o's model and chi².
///
/// An edge i -> j measures z = x_i⁻¹ x_j. Its error is g2o's: the pose z⁻¹ (x_i⁻¹ x_j) as a
/// vector — (x, y, θ normalised to [-π, π)) in SE(2), (translation, vector part of the unit
/// quaternion taken with w >= 0) in SE(3) — and its chi² is eᵀ Ω e, Ω the edge's information
/// matrix (translation first). The graph's chi² is the sum over its edges; it equals g2o's
/// chi² for the same file and poses.
///
/// Poses are kept as given: an angle is not wrapped, a quaternion is not renormalised (g2o files
/// print 6 to 7 digits: their quaternions are unit to about 1e-7). Computations use the wrapped
/// angle and the normalised quaternion. Thread safety: const members may be called concurrently.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "metricmap/common/pose_2d.h"

namespace metricmap {

/// \brief A pose in SE(3): translation and rotation as a (near-)unit quaternion.
struct Pose3D {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

/// \brief a b (a's frame, then b within it); theta wrapped to [-π, π).
Pose2D compose(const Pose2D& a, const Pose2D& b);
/// \brief a⁻¹; theta wrapped to [-π, π).
Pose2D inverse(const Pose2D& a);
/// \brief a b with normalised quaternions; the result's quaternion is normalised.
Pose3D compose(const Pose3D& a, const Pose3D& b);
/// \brief a⁻¹ with a's quaternion normalised.
Pose3D inverse(const Pose3D& a);

/// \brief Largest | |q| - 1 | accepted for a quaternion of a Pose3D in a graph (as TUM files).
inline constexpr double kPoseQuaternionNormTolerance = 1e-2;

/// \brief A pose graph over PoseT (Pose2D or Pose3D) with Dim x Dim information matrices:
/// use PoseGraph2D and PoseGraph3D.
///
/// Vertices have dense indices 0..vertexCount()-1 in the order they were added, and an id (the
/// g2o file's, any value >= 0; ids are looked up in a hash map, so a large id costs nothing).
/// The first vertex added is fixed (the gauge) unless setFixed says otherwise. Edges refer to
/// vertices by index.
template <typename PoseT, int Dim>
class PoseGraph {
 public:
  using Pose = PoseT;
  using Information = Eigen::Matrix<double, Dim, Dim>;
  using Error = Eigen::Matrix<double, Dim, 1>;
  static constexpr int kDim = Dim;

  /// \brief A pose to estimate.
  struct Vertex {
    std::int64_t id = 0;  ///< the id in the file (or given by the caller), unique in the graph
    Pose pose;
    bool fixed = false;  ///< held constant by the optimiser
  };

  /// \brief A relative-pose measurement: `measurement` = x_from⁻¹ x_to.
  struct Edge {
    std::size_t from = 0;  ///< vertex index
    std::size_t to = 0;    ///< vertex index
    Pose measurement;
    Information information = Information::Identity();  ///< symmetric positive definite
    bool loop = false;  ///< a loop closure: the optimiser may give it a robust loss
  };

  /// \brief Add a vertex; the first one added is fixed.
  /// \return its index
  /// \throws std::invalid_argument for a negative or duplicate id or an invalid pose (validatePose)
  std::size_t addVertex(std::int64_t id, const Pose& pose);

  /// \brief Add an edge between two existing, distinct vertices.
  /// \return its index
  /// \throws std::invalid_argument for an index out of range, from == to, an invalid measurement
  /// (validatePose) or information matrix (validateInformation)
  std::size_t addEdge(std::size_t from, std::size_t to, const Pose& measurement,
                      const Information& information, bool loop = false);

  /// \brief The index of the vertex with this id, if any.
  std::optional<std::size_t> find(std::int64_t id) const;

  /// \brief Hold vertex `index` constant in the optimiser (or release it).
  /// \throws std::out_of_range
  void setFixed(std::size_t index, bool fixed);

  /// \brief Replace the pose of vertex `index`. \throws std::out_of_range, std::invalid_argument
  void setPose(std::size_t index, const Pose& pose);

  std::size_t vertexCount() const { return vertices_.size(); }
  std::size_t edgeCount() const { return edges_.size(); }
  const Vertex& vertex(std::size_t index) const { return vertices_.at(index); }
  const Edge& edge(std::size_t index) const { return edges_.at(index); }
  const std::vector<Vertex>& vertices() const { return vertices_; }
  const std::vector<Edge>& edges() const { return edges_; }

  /// \brief The error of edge `index` at the current poses (g2o's, see the file comment).
  Error edgeError(std::size_t index) const;
  /// \brief eᵀ Ω e of edge `index` at the current poses.
  double edgeChi2(std::size_t index) const;
  /// \brief The sum of edgeChi2 over all edges.
  double chi2() const;

  /// \brief \throws std::invalid_argument unless every value is finite, every translation
  /// component within kMaxTranslation, (SE(2)) theta within kMaxAngle and (SE(3)) the
  /// quaternion's norm within kPoseQuaternionNormTolerance of 1.
  static void validatePose(const Pose& pose);
  /// \brief \throws std::invalid_argument unless every entry is finite, the matrix is symmetric
  /// and it is positive definite (its Cholesky factorisation succeeds).
  static void validateInformation(const Information& information);

 private:
  std::vector<Vertex> vertices_;
  std::vector<Edge> edges_;
  std::unordered_map<std::int64_t, std::size_t> index_;
};

/// \brief SE(2) pose graph: 3x3 information over (x, y, θ).
using PoseGraph2D = PoseGraph<Pose2D, 3>;
/// \brief SE(3) pose graph: 6x6 information over (translation, quaternion vector part), as g2o.
using PoseGraph3D = PoseGraph<Pose3D, 6>;

extern template class PoseGraph<Pose2D, 3>;
extern template class PoseGraph<Pose3D, 6>;

}  // namespace metricmap
