#include "metricmap/datasets/reference_file.h"

#include "metricmap/exceptions.h"
#include "metricmap/io/trajectory.h"

namespace metricmap {

Trajectory readReferencePoses(const std::string& path, std::size_t count) {
  Trajectory t = readTrajectoryFile(path);
  if (t.size() != count) {
    throw InputError(path + ": " + std::to_string(t.size()) + " pose line(s) for " +
                     std::to_string(count) + " scan(s)");
  }
  return t;
}

std::vector<double> readStampsFile(const std::string& path, std::size_t count) {
  std::vector<double> stamps = readStamps(path);
  if (count != kAnyCount && stamps.size() != count) {
    throw InputError(path + ": " + std::to_string(stamps.size()) + " stamp(s) for " +
                     std::to_string(count) + " scan(s)");
  }
  return stamps;
}

}  // namespace metricmap
