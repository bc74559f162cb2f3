#include "metricmap/io/cell_csv.h"

#include <sstream>

namespace metricmap {

std::string gridCellsCsv(const std::vector<GridCell>& cells) {
  std::ostringstream os;
  os.precision(9);
  os << "ix,iy,iz,count,mean_x,mean_y,mean_z\n";
  for (const GridCell& c : cells) {
    os << c.index[0] << "," << c.index[1] << "," << c.index[2] << "," << c.count << ","
       << c.mean.x() << "," << c.mean.y() << "," << c.mean.z() << "\n";
  }
  return os.str();
}

std::string octreeLeavesCsv(const std::vector<OctreeNode>& nodes) {
  std::ostringstream os;
  os.precision(9);
  os << "node,depth,min_x,min_y,min_z,max_x,max_y,max_z,count,mean_x,mean_y,mean_z\n";
  for (std::size_t id = 0; id < nodes.size(); ++id) {
    const OctreeNode& n = nodes[id];
    if (!n.isLeaf()) continue;
    os << id << "," << n.depth << "," << n.min.x() << "," << n.min.y() << "," << n.min.z() << ","
       << n.max.x() << "," << n.max.y() << "," << n.max.z() << "," << n.count << "," << n.mean.x()
       << "," << n.mean.y() << "," << n.mean.z() << "\n";
  }
  return os.str();
}

}  // namespace metricmap
