// DistanceField against OctoMap's dynamicEDT3D (DynamicEDTOctomap) as the oracle: the log-odds
// map of the first bundled KITTI scan, the same box and clamp, every voxel.
#include <cmath>
#include <string>

#include <dynamicEDT3D/dynamicEDTOctomap.h>
#include <octomap/OcTree.h>
#include <pcl/common/transforms.h>

#include <gtest/gtest.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/distance/distance_field.h"
#include "metricmap/distance/distance_sources.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {
namespace {

TEST(DistanceVsDynamicEDT, EveryVoxelOfAKittiScanMap) {
  const KittiSequence seq{std::string(METRICMAP_DATA_DIR) + "/kitti_odometry_00", "00"};
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const auto poses = readKittiPoses(seq.poses(), 1);
  LogOddsParams lp;
  lp.resolution = 0.4;
  lp.max_range = 20.0;
  LogOddsMap map(lp);
  pcl::PointCloud<pcl::PointXYZ> scan, world;
  loadCloud(seq.scan(0), scan);
  const Eigen::Isometry3d to_world = kittiScanToWorld(poses[0], tr, KittiWorld::Velodyne);
  pcl::transformPointCloud(scan, world, to_world.matrix().cast<float>());
  map.insertScan(world, to_world.translation().cast<float>());

  DistanceFieldParams p;
  p.max_distance = 2.0;
  const DistanceField field(occupancyBoxOf(map, p), p);

  octomap::OcTree tree(lp.resolution);
  map.forEachKnown([&](const VoxelKey& k, float lo) {
    const Eigen::Vector3d c = map.centerOf(k);
    tree.setNodeValue(octomap::point3d(static_cast<float>(c.x()), static_cast<float>(c.y()),
                                       static_cast<float>(c.z())),
                      lo, true);
  });
  tree.updateInnerOccupancy();
  const auto pt = [](const Eigen::Vector3d& v) {
    return octomap::point3d(static_cast<float>(v.x()), static_cast<float>(v.y()),
                            static_cast<float>(v.z()));
  };
  const auto& s = field.shape();
  const Eigen::Vector3d top =
      field.origin() + Eigen::Vector3d(s[0] - 1, s[1] - 1, s[2] - 1) * field.resolution();
  DynamicEDTOctomap edt(static_cast<float>(p.max_distance), &tree, pt(field.origin()), pt(top),
                        false);
  edt.update();

  std::size_t compared = 0, within = 0, off = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < s[0]; ++i) {
    for (std::size_t j = 0; j < s[1]; ++j) {
      for (std::size_t k = 0; k < s[2]; ++k) {
        const Eigen::Vector3d c = field.origin() + Eigen::Vector3d(i, j, k) * field.resolution();
        const float raw = edt.getDistance(tree.coordToKey(pt(c)));
        ASSERT_GE(raw, 0.0f) << "outside dynamicEDT3D's box at " << i << "," << j << "," << k;
        // dynamicEDT3D reports cells beyond its clamp at a value above it: clamp alike
        const float theirs = std::min(raw, static_cast<float>(p.max_distance));
        const float ours = field.at(i, j, k);
        ++compared;
        within += ours < p.max_distance;
        const double diff = std::abs(static_cast<double>(ours) - theirs);
        worst = std::max(worst, diff);
        if (diff > 1e-4 && off++ < 5) {
          ADD_FAILURE() << "voxel " << i << "," << j << "," << k << ": " << ours
                        << " vs dynamicEDT3D " << theirs;
        }
      }
    }
  }
  EXPECT_EQ(off, 0u);
  EXPECT_EQ(compared, field.voxels());
  EXPECT_GT(within, compared / 10) << "too few voxels below the clamp to compare";
  std::cout << "compared " << compared << " voxels (" << within
            << " below the clamp) with dynamicEDT3D, largest difference " << worst << " m\n";
}

}  // namespace
}  // namespace metricmap
