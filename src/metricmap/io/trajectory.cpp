#include "metricmap/io/trajectory.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <Eigen/Geometry>

#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {

std::vector<Eigen::Isometry3d> readTumTrajectory(const std::string& path, std::size_t frames) {
  requireRegularFile(path);
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  std::vector<Eigen::Isometry3d> poses;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line) && poses.size() < frames; ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    std::istringstream is(line);
    double v[8];
    std::string token;
    for (double& x : v) {
      try {
        if (!(is >> token)) throw std::invalid_argument("too few numbers");
        x = parseFiniteDouble(token, "value");
      } catch (const std::invalid_argument&) {
        throw InputError(path + ": line " + std::to_string(n) +
                         " is not 'timestamp tx ty tz qx qy qz qw' (8 finite numbers)");
      }
    }
    if (is >> token) {
      throw InputError(path + ": line " + std::to_string(n) +
                       " has more than 8 numbers ('timestamp tx ty tz qx qy qz qw')");
    }
    Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    if (q.norm() < 1e-9)
      throw InputError(path + ": line " + std::to_string(n) + ": zero quaternion");
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = q.normalized().toRotationMatrix();
    t.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    poses.push_back(t);
  }
  if (poses.size() < frames) {
    throw InputError(path + ": " + std::to_string(poses.size()) + " pose(s) for " +
                     std::to_string(frames) + " frame(s)");
  }
  return poses;
}

}  // namespace metricmap
