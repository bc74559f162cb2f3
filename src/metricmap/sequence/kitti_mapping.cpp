#include "metricmap/sequence/kitti_mapping.h"

#include <algorithm>
#include <chrono>
#include <random>
#include <stdexcept>

#include <unistd.h>

#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/registration/scan_registration.h"

namespace metricmap {

std::vector<Eigen::Isometry3d> KittiMappingRun::posesOfScans() const {
  std::vector<Eigen::Isometry3d> out;
  for (const Eigen::Isometry3d& p : mapper->poses()) out.push_back(kittiPoseOfScan(p, tr, world));
  return out;
}

double KittiMappingRun::registerSeconds() const {
  double seconds = 0.0;
  for (const FrameReport& r : reports) seconds += r.seconds_register;
  return seconds;
}

double KittiMappingRun::occupancySeconds() const {
  double seconds = 0.0;
  for (const FrameReport& r : reports) seconds += r.seconds_occupancy;
  return seconds;
}

KittiMappingRun mapKittiSequence(const KittiMappingOptions& o,
                                 const KittiMappingObserver& observer) {
  if (o.frames.empty()) throw std::invalid_argument("mapKittiSequence: no frames");
  const KittiSequence& seq = o.sequence;
  for (std::size_t f : o.frames) {  // every scan must exist before any work is done
    if (access(seq.scan(f).c_str(), R_OK) != 0) throw InputError(seq.scan(f) + ": missing frame");
  }
  KittiMappingRun run;
  run.world = o.world;
  run.tr = readKittiCalibTr(seq.calib());
  const bool odometry = o.mapper.odometry;  // no pose file needed, none read
  const std::size_t last = *std::max_element(o.frames.begin(), o.frames.end());
  const std::vector<Eigen::Isometry3d> poses =
      odometry ? std::vector<Eigen::Isometry3d>() : readKittiPoses(seq.poses(), last + 1);
  ScanMapperConfig config = o.mapper;
  // Odometry poses start at the first frame's velodyne; the world is its camera 0 or itself.
  if (odometry && o.world == KittiWorld::Camera) config.odometry_origin = run.tr;
  run.mapper = std::make_unique<ScanMapper>(config);
  ScanMapper& mapper = *run.mapper;
  const bool perturbs = o.perturb_translation > 0.0 || o.perturb_rotation_deg > 0.0;
  std::mt19937 rng(o.seed);
  KittiMappingTotals& tot = run.totals;
  for (std::size_t k = 0; k < o.frames.size(); ++k) {
    const auto t = std::chrono::steady_clock::now();
    pcl::PointCloud<pcl::PointXYZ> scan;
    loadCloud(seq.scan(o.frames[k]), scan);
    tot.load_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    try {
      if (odometry) {
        run.reports.push_back(mapper.addScan(scan));
        run.odometry.push_back(mapper.lastOdometry());
      } else {
        run.truths.push_back(kittiScanToWorld(poses[o.frames[k]], run.tr, o.world));
        Eigen::Isometry3d pose = run.truths.back();
        if (perturbs && k > 0) {
          pose = perturbPose(pose, o.perturb_translation, o.perturb_rotation_deg, rng);
        }
        run.reports.push_back(mapper.addScan(scan, pose));
      }
    } catch (const InputError& e) {
      throw InputError(seq.scan(o.frames[k]) + ": " + e.what());
    }
    const FrameReport& r = run.reports.back();
    tot.points_read += r.points_read;
    tot.points_kept += r.points_kept;
    tot.points_mapped += r.points_mapped;
    tot.transform_s += r.seconds_transform + r.seconds_register;
    tot.map_s += r.seconds_map;
    if (observer) observer(k + 1, o.frames.size(), tot);
  }
  return run;
}

}  // namespace metricmap
