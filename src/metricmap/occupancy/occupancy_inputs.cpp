#include "metricmap/occupancy/occupancy_inputs.h"

#include <filesystem>

#include <unistd.h>

#include "metricmap/io/bag_reader.h"

namespace metricmap {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool isKittiRoot(const std::string& path) {
  return access((path + "/sequences").c_str(), F_OK) == 0;
}

/// A scan source other than a KITTI root: a folder of scans (with poses.txt), a .txt list, a
/// CARMEN log, a ROS bag.
bool isScanSource(const std::string& p) {
  std::error_code ec;
  return std::filesystem::is_directory(p, ec) || endsWith(p, ".txt") || endsWith(p, ".clf") ||
         endsWith(p, ".log") || endsWith(p, ".gz") || endsWith(p, ".bz2") || looksLikeBag(p);
}

}  // namespace

OccupancyInputKind occupancyInputKind(const std::vector<std::string>& inputs) {
  if (inputs.size() != 1) return OccupancyInputKind::PcdScans;
  const std::string& p = inputs[0];
  if (endsWith(p, ".bt") || endsWith(p, ".ot")) return OccupancyInputKind::OctomapFile;
  if (isKittiRoot(p)) return OccupancyInputKind::KittiRoot;
  if (isScanSource(p)) return OccupancyInputKind::ScanSource;
  return OccupancyInputKind::PcdScans;
}

}  // namespace metricmap
