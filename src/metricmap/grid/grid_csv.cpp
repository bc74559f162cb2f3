#include "metricmap/grid/grid_csv.h"

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

}  // namespace metricmap
