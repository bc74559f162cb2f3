#include <array>
#include <stdexcept>

#include "metricmap/octree/octree_types.h"

namespace metricmap {

OctreeBox OctreeResult::bounds(std::size_t id) const {
  if (id >= nodes.size()) throw std::out_of_range("octree node id out of range");
  // The octants from the node up to the root, then the halvings from the root down.
  std::array<unsigned, 64> path{};
  unsigned depth = 0;
  for (std::size_t at = id; nodes[at].parent != OctreeNode::kNone && depth < path.size();) {
    const std::size_t parent = nodes[at].parent;
    path[depth++] = static_cast<unsigned>(at - nodes[parent].first_child);
    at = parent;
  }
  OctreeBox box = root;
  while (depth-- > 0) box = childBox(box, path[depth]);
  return box;
}

std::vector<OctreeBox> OctreeResult::allBounds() const {
  std::vector<OctreeBox> boxes(nodes.size());
  if (nodes.empty()) return boxes;
  boxes[0] = root;
  for (std::size_t id = 0; id < nodes.size(); ++id) {  // children follow their parents
    if (nodes[id].isLeaf()) continue;
    for (unsigned c = 0; c < 8; ++c) boxes[nodes[id].child(c)] = childBox(boxes[id], c);
  }
  return boxes;
}

}  // namespace metricmap
