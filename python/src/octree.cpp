// metricmap.octree: AdaptiveOctree's kernel on a numpy array; nodes as views of the result.
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <pybind11/stl.h>

#include "arrays.h"
#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/octree/octree_kernel.h"

namespace metricmap::python {

namespace {

py::dict statisticsDict(const OctreeStatistics& s) {
  py::dict d;
  d["total_nodes"] = s.total_nodes;
  d["leaf_nodes"] = s.leaf_nodes;
  d["internal_nodes"] = s.internal_nodes;
  d["occupied_leaves"] = s.occupied_leaves;
  d["empty_leaves"] = s.empty_leaves;
  d["mean_points_per_occupied_leaf"] = s.mean_points_per_occupied_leaf;
  d["points"] = s.points;
  d["max_depth"] = s.max_depth;
  d["skipped_points"] = s.skipped_points;
  return d;
}

/// A view of one member of every node: `rows` x `cols` values of T starting at `first`.
template <typename T>
py::array nodeView(py::object self, const T* first, std::size_t rows, py::ssize_t cols) {
  if (cols == 1)
    return viewOf<T>(rows ? first : nullptr, {py::ssize_t(rows)}, {py::ssize_t(sizeof(OctreeNode))},
                     self);
  return viewOf<T>(rows ? first : nullptr, {py::ssize_t(rows), cols},
                   {py::ssize_t(sizeof(OctreeNode)), py::ssize_t(sizeof(T))}, self);
}

/// Lower (or upper) corners of every node as a new (K, 3) array.
py::array_t<double> corners(const OctreeResult& r, bool upper) {
  py::array_t<double> a({py::ssize_t(r.nodes.size()), py::ssize_t(3)});
  double* d = a.mutable_data();
  const std::vector<OctreeBox> boxes = r.allBounds();
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Eigen::Vector3d& c = upper ? boxes[i].max : boxes[i].min;
    for (int k = 0; k < 3; ++k) d[3 * i + k] = c[k];
  }
  return a;
}

}  // namespace

void initOctree(py::module_& m) {
  py::class_<OctreeResult, std::shared_ptr<OctreeResult>>(m, "Octree", R"doc(
The nodes of an adaptive octree build (see :func:`octree`); node 0 is the root.

Node arrays are read-only views of the nodes held by this object (they keep it alive).
)doc")
      .def_property_readonly(
          "statistics", [](const OctreeResult& r) { return statisticsDict(r.stats); },
          "dict: total_nodes, leaf_nodes, internal_nodes, occupied_leaves, empty_leaves, "
          "mean_points_per_occupied_leaf, points, max_depth, skipped_points.")
      .def_property_readonly(
          "mins", [](const OctreeResult& r) { return corners(r, false); },
          "(K, 3) float64 (new array): lower corner of each node, metres (nodes do not store "
          "their bounds; they are computed from the root box).")
      .def_property_readonly(
          "maxs", [](const OctreeResult& r) { return corners(r, true); },
          "(K, 3) float64 (new array): upper corner of each node, metres.")
      .def_property_readonly(
          "means",
          [](py::object self) {
            const auto& r = self.cast<const OctreeResult&>();
            return nodeView(self, r.nodes.empty() ? nullptr : r.nodes[0].mean.data(),
                            r.nodes.size(), 3);
          },
          "(K, 3) float64 view: mean of each node's points (zero when empty).")
      .def_property_readonly(
          "counts",
          [](py::object self) {
            const auto& r = self.cast<const OctreeResult&>();
            return nodeView(self, r.nodes.empty() ? nullptr : &r.nodes[0].count, r.nodes.size(), 1);
          },
          "(K,) uint32 view: points inside each node.")
      .def_property_readonly(
          "depths",
          [](py::object self) {
            const auto& r = self.cast<const OctreeResult&>();
            return nodeView(self, r.nodes.empty() ? nullptr : &r.nodes[0].depth, r.nodes.size(), 1);
          },
          "(K,) uint32 view: depth of each node (root = 0).")
      .def_property_readonly(
          "first_points",
          [](py::object self) {
            const auto& r = self.cast<const OctreeResult&>();
            return nodeView(self, r.nodes.empty() ? nullptr : &r.nodes[0].first_point,
                            r.nodes.size(), 1);
          },
          "(K,) uint32 view: where each node's points start in point_order.")
      .def_property_readonly(
          "parents",
          [](const OctreeResult& r) {
            py::array_t<std::int64_t> a(static_cast<py::ssize_t>(r.nodes.size()));
            auto* d = a.mutable_data();
            for (std::size_t i = 0; i < r.nodes.size(); ++i)
              d[i] = r.nodes[i].parent == OctreeNode::kNone
                         ? -1
                         : static_cast<std::int64_t>(r.nodes[i].parent);
            return a;
          },
          "(K,) int64 (new array): parent of each node, -1 for the root.")
      .def_property_readonly(
          "first_children",
          [](const OctreeResult& r) {
            py::array_t<std::int64_t> a(static_cast<py::ssize_t>(r.nodes.size()));
            auto* d = a.mutable_data();
            for (std::size_t i = 0; i < r.nodes.size(); ++i)
              d[i] = r.nodes[i].isLeaf() ? -1 : static_cast<std::int64_t>(r.nodes[i].first_child);
            return a;
          },
          "(K,) int64 (new array): first of each node's 8 children (octant bit 0: upper x, bit "
          "1: upper y, bit 2: upper z), -1 for a leaf.")
      .def_property_readonly(
          "leaves",
          [](const OctreeResult& r) {
            py::array_t<bool> a(static_cast<py::ssize_t>(r.nodes.size()));
            auto* d = a.mutable_data();
            for (std::size_t i = 0; i < r.nodes.size(); ++i) d[i] = r.nodes[i].isLeaf();
            return a;
          },
          "(K,) bool (new array): True for leaves.")
      .def_property_readonly(
          "occupied_leaves",
          [](py::object self) {
            const auto& r = self.cast<const OctreeResult&>();
            return viewOf<std::size_t>(
                r.occupied_leaves.empty() ? nullptr : r.occupied_leaves.data(),
                {py::ssize_t(r.occupied_leaves.size())}, {py::ssize_t(sizeof(std::size_t))}, self);
          },
          "(L,) uint64 view: node ids of the occupied leaves, depth-first (Morton) order.")
      .def_property_readonly(
          "point_order",
          [](py::object self) {
            const auto& r = self.cast<const OctreeResult&>();
            return viewOf<std::uint32_t>(r.point_order.empty() ? nullptr : r.point_order.data(),
                                         {py::ssize_t(r.point_order.size())},
                                         {py::ssize_t(sizeof(std::uint32_t))}, self);
          },
          "(P,) uint32 view: input rows grouped node by node; node k holds "
          "point_order[first_point : first_point + count].")
      .def("__len__", [](const OctreeResult& r) { return r.nodes.size(); })
      .def("__repr__", [](const OctreeResult& r) {
        return "<metricmap.Octree " + std::to_string(r.nodes.size()) + " nodes, " +
               std::to_string(r.stats.leaf_nodes) + " leaves>";
      });

  m.def(
      "octree",
      [](ArrayLike points, std::int64_t max_points, double min_cell_size, bool cubic,
         std::optional<std::pair<ArrayLike, ArrayLike>> root_box, unsigned threads) {
        // named as given: 1e39 is not a float (it would read inf), 1e-300 would read 0
        if (beyondFloatRange(min_cell_size) || belowFloatRange(min_cell_size))
          throw py::value_error("min_cell_size " + formatNumber(min_cell_size) +
                                " is outside the single-precision range");
        if (max_points < 0)
          throw py::value_error("max_points must be >= 0, got " + std::to_string(max_points));
        OctreeParams params;
        params.max_points_per_leaf = static_cast<std::size_t>(max_points);
        params.min_cell_size = static_cast<float>(min_cell_size);
        params.cubic_root = cubic;
        params.threads = threads;
        if (root_box) {
          params.has_root_box = true;
          params.root_min = vector3From(root_box->first, "root_box[0]");
          params.root_max = vector3From(root_box->second, "root_box[1]");
        }
        validateOctreeParams(params);
        PointsArray p = pointsFromArray(points, "points");
        if (p.span.size > 0xffffffffu) throw py::value_error("points: more than 2**32 - 1 rows");
        auto result = std::make_shared<OctreeResult>();
        {
          py::gil_scoped_release release;
          OctreeWorkspace workspace;
          buildOctree(p.span, params, workspace, *result);
        }
        return result;
      },
      py::arg("points"), py::arg("max_points") = 100, py::arg("min_cell_size") = 1.0,
      py::arg("cubic") = false, py::arg("root_box") = py::none(), py::arg("threads") = 0u,
      R"doc(
Build an adaptive octree: a node splits into 8 while it holds more than `max_points` points
and its largest edge is longer than `min_cell_size` (AdaptiveOctree).

Parameters
----------
points : array_like, shape (N, 3) or (N, 4)
    Metres; read in place when C-contiguous float32, else converted once. NaN/Inf skipped.
max_points : int
    Split while a node holds more than this (>= 0).
min_cell_size : float
    ... and its largest edge is longer than this, metres (>= 0).
cubic : bool
    Root = cube of the largest extent instead of the bounding box.
root_box : (array_like (3,), array_like (3,)), optional
    Root bounds (min, max) instead of the cloud's; points outside are skipped and counted.
threads : int
    0 = all hardware threads; the result does not depend on it.

Returns
-------
Octree
    statistics and per-node arrays (mins, maxs, means, counts, depths, parents,
    first_children, leaves), occupied_leaves and point_order.
)doc");
}

}  // namespace metricmap::python
