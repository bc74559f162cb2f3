#include "metricmap/localization/map_alignment_3d.h"

#include <cmath>

namespace metricmap {

MapAlignment3D mapOverlap(const std::vector<Eigen::Vector3d>& scan, const VoxelHashMap& map,
                          const Eigen::Isometry3d& pose, double distance) {
  MapAlignment3D a;
  a.pose = pose;
  if (scan.empty()) return a;
  std::size_t hits = 0;
  double sq = 0.0;
  Eigen::Vector3d q;
  VoxelHashMap::Neighbourhood hood;
  for (const Eigen::Vector3d& s : scan) {
    const Eigen::Vector3d w = pose * s;
    if (map.nearestCached(w, distance, hood, q)) {
      ++hits;
      sq += (w - q).squaredNorm();
    }
  }
  a.overlap = double(hits) / double(scan.size());
  a.rmse = hits > 0 ? std::sqrt(sq / double(hits)) : 0.0;
  return a;
}

MapAlignment3D alignToMap(const std::vector<Eigen::Vector3d>& scan, const VoxelHashMap& map,
                          const Eigen::Isometry3d& initial, const MapAlignmentParams& p,
                          PointToPointIcpWorkspace* workspace) {
  PointToPointIcpParams icp;
  icp.max_iterations = p.iterations;
  icp.convergence = 1e-4;
  icp.threshold = p.coarse_threshold;
  // The fixed map constrains every direction the scan sees; nothing is held at the guess.
  icp.degeneracy_ratio = 0.0;
  Eigen::Isometry3d pose = alignPointToPoint(scan, map, initial, icp, workspace).pose;
  if (p.fine_threshold < p.coarse_threshold) {
    icp.threshold = p.fine_threshold;
    pose = alignPointToPoint(scan, map, pose, icp, workspace).pose;
  }
  // Products of poses drift off the rotations: the nearest rotation, so that the track stays rigid.
  pose.linear() = Eigen::Quaterniond(pose.linear()).normalized().toRotationMatrix();
  return mapOverlap(scan, map, pose, p.overlap_distance);
}

}  // namespace metricmap
