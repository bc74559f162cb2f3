#include "metricmap/occupancy/scan_casting.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <pcl/common/transforms.h>

#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// `name`: the scan's file, named in any error about the scan (a point outside the key space, a
/// scan too large for the budget).
void insertInto(LogOddsMap& map, const Cloud& cloud, const Eigen::Vector3f* origin,
                std::size_t dropped, ScanCastTotals& totals, const std::string& name) {
  const auto t = std::chrono::steady_clock::now();
  ScanInsertReport r;
  try {
    r = origin ? map.insertScan(cloud, *origin) : map.insertScan(cloud);
  } catch (const CapacityError& e) {
    throw CapacityError(name + ": " + e.what());
  } catch (const InputError& e) {
    throw InputError(name + ": " + e.what());
  }
  totals.insert_s += secondsSince(t);
  ++totals.frames;
  totals.points += r.points + dropped;
  totals.beams += r.beams;
  totals.cut += r.beams_cut;
  totals.non_finite += r.non_finite + dropped;
}

bool isPcd(const std::string& path) {
  return path.size() > 4 && (path.compare(path.size() - 4, 4, ".pcd") == 0 ||
                             path.compare(path.size() - 4, 4, ".PCD") == 0);
}

}  // namespace

void castKittiFrames(LogOddsMap& map, const KittiSequence& sequence,
                     const std::vector<std::size_t>& frames, std::size_t first, std::size_t last,
                     KittiWorld world, ScanCastTotals& totals, const CastProgress& progress) {
  if (frames.empty() || first >= last) return;
  for (std::size_t k = first; k < last; ++k) {
    const std::string scan = sequence.scan(frames[k]);
    if (access(scan.c_str(), R_OK) != 0) throw InputError(scan + ": missing frame");
  }
  const Eigen::Isometry3d tr = readKittiCalibTr(sequence.calib());
  const auto poses =
      readKittiPoses(sequence.poses(), *std::max_element(frames.begin(), frames.end()) + 1);
  for (std::size_t k = first; k < last; ++k) {
    const auto t = std::chrono::steady_clock::now();
    Cloud scan, world_scan;
    const LoadReport lr = loadCloud(sequence.scan(frames[k]), scan);
    const Eigen::Isometry3d to_world = kittiScanToWorld(poses[frames[k]], tr, world);
    pcl::transformPointCloud(scan, world_scan, to_world.matrix().cast<float>());
    totals.load_s += secondsSince(t);
    const Eigen::Vector3f origin = to_world.translation().cast<float>();
    insertInto(map, world_scan, &origin, lr.nonfinite_dropped, totals, sequence.scan(frames[k]));
    if (progress) progress(k + 1 - first, last - first);
  }
}

void castSourceFrames(LogOddsMap& map, ScanSource& source, const std::vector<std::size_t>& frames,
                      const std::vector<Eigen::Isometry3d>& poses, std::size_t first,
                      std::size_t last, ScanCastTotals& totals, const CastProgress& progress) {
  if (poses.size() != frames.size()) {
    throw std::invalid_argument(std::to_string(poses.size()) + " pose(s) for " +
                                std::to_string(frames.size()) + " frame(s)");
  }
  for (std::size_t k = first; k < last && k < frames.size(); ++k) {
    const auto t = std::chrono::steady_clock::now();
    const Scan scan = source.scan(frames[k]);
    Cloud world_scan;
    pcl::transformPointCloud(scan.points, world_scan, poses[k].matrix().cast<float>());
    totals.load_s += secondsSince(t);
    const Eigen::Vector3f origin = poses[k].translation().cast<float>();
    insertInto(map, world_scan, &origin, 0, totals, scan.name);
    if (progress) progress(k + 1 - first, last - first);
  }
}

void castPcdScans(LogOddsMap& map, const std::vector<std::string>& paths, std::size_t first,
                  std::size_t last, ScanCastTotals& totals, const CastProgress& progress) {
  for (const std::string& path : paths) {
    if (!isPcd(path))
      throw InputError(path +
                       ": scans must be PCD files (VIEWPOINT = sensor pose) or one "
                       "KITTI root");
  }
  for (std::size_t k = first; k < last && k < paths.size(); ++k) {
    const auto t = std::chrono::steady_clock::now();
    requirePcdViewpoint(paths[k]);
    Cloud scan;
    const LoadReport lr = loadCloud(paths[k], scan);
    totals.load_s += secondsSince(t);
    totals.warnings.insert(totals.warnings.end(), lr.warnings.begin(), lr.warnings.end());
    insertInto(map, scan, nullptr, lr.nonfinite_dropped, totals, paths[k]);
    if (progress) progress(k + 1 - first, last - first);
  }
}

void requirePcdViewpoint(const std::string& path) {
  std::ifstream in = openRegularFile(path);  // a FIFO would block here
  std::string line;
  for (int i = 0; i < 32 && std::getline(in, line); ++i) {
    if (line.rfind("VIEWPOINT", 0) == 0) return;
    if (line.rfind("DATA", 0) == 0) break;
  }
  throw InputError(path + ": no VIEWPOINT line: the sensor pose (origin of the beams) is unknown");
}

}  // namespace metricmap
