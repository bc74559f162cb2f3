#include "metricmap/octree/octree_csv.h"

#include <sstream>
#include <vector>

namespace metricmap {

std::string octreeLeavesCsv(const OctreeResult& octree) {
  std::ostringstream os;
  os.precision(9);
  os << "node,depth,min_x,min_y,min_z,max_x,max_y,max_z,count,mean_x,mean_y,mean_z\n";
  const std::vector<OctreeBox> boxes = octree.allBounds();
  for (std::size_t id = 0; id < octree.nodes.size(); ++id) {
    const OctreeNode& n = octree.nodes[id];
    if (!n.isLeaf()) continue;
    const OctreeBox& b = boxes[id];
    os << id << "," << n.depth << "," << b.min.x() << "," << b.min.y() << "," << b.min.z() << ","
       << b.max.x() << "," << b.max.y() << "," << b.max.z() << "," << n.count << "," << n.mean.x()
       << "," << n.mean.y() << "," << n.mean.z() << "\n";
  }
  return os.str();
}

}  // namespace metricmap
