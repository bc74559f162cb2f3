#pragma once
// KITTI frames of the bundled sequence in the velodyne world (z up), with the sensor origin:
// the input of the occupancy tests.
#include <vector>

#include <pcl/common/transforms.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/io/cloud_reader.h"
#include "test_data.h"

namespace metricmap::test {

struct WorldScan {
  pcl::PointCloud<pcl::PointXYZ> points;  // world frame
  Eigen::Vector3f origin;
};

inline WorldScan kittiWorldScan(std::size_t frame) {
  const KittiSequence seq{dataPath("kitti_odometry_00"), "00"};
  pcl::PointCloud<pcl::PointXYZ> scan;
  loadCloud(seq.scan(frame), scan);
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const auto poses = readKittiPoses(seq.poses(), frame + 1);
  const Eigen::Isometry3d to_world = kittiScanToWorld(poses[frame], tr, KittiWorld::Velodyne);
  WorldScan out;
  pcl::transformPointCloud(scan, out.points, to_world.matrix().cast<float>());
  out.origin = to_world.translation().cast<float>();
  return out;
}

/// Every `step`-th point, from the first: a deterministic subsample.
inline WorldScan subsample(const WorldScan& in, std::size_t step) {
  WorldScan out;
  out.origin = in.origin;
  for (std::size_t i = 0; i < in.points.size(); i += step) out.points.push_back(in.points[i]);
  return out;
}

}  // namespace metricmap::test
