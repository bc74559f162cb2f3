#include "metricmap/datasets/reference_file.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "metricmap/common/parse_number.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/trajectory.h"

namespace metricmap {
namespace {

bool isDataLine(const std::string& line) {
  const auto at = line.find_first_not_of(" \t\r");
  return at != std::string::npos && line[at] != '#';
}

}  // namespace

std::size_t countDataLines(const std::string& path) {
  std::ifstream in = openRegularFile(path, std::ios::in);
  std::size_t n = 0;
  std::string line;
  while (std::getline(in, line)) n += isDataLine(line) ? 1 : 0;
  if (in.bad()) throw InputError(path + ": read error");
  return n;
}

Trajectory readReferencePoses(const std::string& path, std::size_t count) {
  const std::size_t lines = countDataLines(path);
  if (lines != count) {
    throw InputError(path + ": " + std::to_string(lines) + " pose line(s) for " +
                     std::to_string(count) + " scan(s)");
  }
  std::ifstream in = openRegularFile(path, std::ios::in);
  std::string line;
  std::size_t tokens = 0;
  while (std::getline(in, line)) {
    if (!isDataLine(line)) continue;
    std::istringstream is(line);
    std::string t;
    while (is >> t) ++tokens;
    break;
  }
  Trajectory out;
  if (tokens == 12) {
    out.poses = readKittiPoses(path, count);
  } else if (tokens == 8) {
    out.poses = readTumTrajectory(path, count);
    std::ifstream again = openRegularFile(path, std::ios::in);
    while (std::getline(again, line)) {
      if (!isDataLine(line)) continue;
      std::istringstream is(line);
      std::string t;
      is >> t;
      out.stamps.push_back(parseFiniteDouble(t, path + ": stamp"));
    }
  } else {
    throw InputError(path + ": the first pose line has " + std::to_string(tokens) +
                     " numbers; KITTI rows have 12, TUM rows 8");
  }
  return out;
}

std::vector<double> readStampsFile(const std::string& path, std::size_t count) {
  std::ifstream in = openRegularFile(path, std::ios::in);
  std::vector<double> stamps;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (!isDataLine(line)) continue;
    const std::string where = path + ": line " + std::to_string(n);
    if (stamps.size() == count) {
      throw InputError(path + ": more stamps than the " + std::to_string(count) + " scan(s)");
    }
    std::istringstream is(line);
    std::string token, extra;
    is >> token;
    if (is >> extra) throw InputError(where + ": more than one number");
    double t = 0.0;
    try {
      t = parseFiniteDouble(token, "stamp");
    } catch (const std::invalid_argument&) {
      throw InputError(where + ": '" + token + "' is not a finite number");
    }
    if (!stamps.empty() && !(t > stamps.back())) {
      throw InputError(where + ": stamp " + token + " is not after the previous one");
    }
    stamps.push_back(t);
  }
  if (in.bad()) throw InputError(path + ": read error");
  if (stamps.size() != count) {
    throw InputError(path + ": " + std::to_string(stamps.size()) + " stamp(s) for " +
                     std::to_string(count) + " scan(s)");
  }
  return stamps;
}

}  // namespace metricmap
