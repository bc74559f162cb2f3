// The odometry over a scan source: a hand-carried scanner's folder at the defaults (range
// window, voxel and coarse stage from the first scan) against its reference poses, with the
// per-frame error recomputed here from the matrices; KITTI through the pipeline equals
// LidarOdometry called scan by scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/sequence/odometry_run.h"

namespace {

const std::string kBalm = std::string(METRICMAP_SHARED_DATA_DIR) + "/balm_realworld_dev";

double angleDeg(const Eigen::Matrix3d& r) {
  const double c = std::clamp((r.trace() - 1.0) / 2.0, -1.0, 1.0);
  return std::acos(c) * 180.0 / M_PI;
}

}  // namespace

TEST(OdometryRun, HandCarriedScannerAtTheDefaults) {
  auto source = metricmap::openScanSource(kBalm);
  metricmap::OdometryRunOptions options;  // auto profile: nothing tuned by hand
  options.config.threads = 1;
  const metricmap::OdometryRun run = metricmap::runOdometry(*source, options);
  ASSERT_EQ(run.trajectory.size(), 40u);
  EXPECT_TRUE(run.profile.used);
  EXPECT_GT(run.config.coarse_voxel_size, run.config.voxel_size);
  ASSERT_TRUE(run.rpe.has_value());

  // The per-frame error, from the matrices: (Q_{k-1}^-1 Q_k)^-1 (P_{k-1}^-1 P_k).
  const auto& ref = source->info().reference.poses;
  std::vector<double> t_err, r_err;
  for (std::size_t k = 1; k < 40; ++k) {
    const Eigen::Matrix4d q = ref[k - 1].matrix().inverse() * ref[k].matrix();
    const Eigen::Matrix4d p =
        run.trajectory.poses[k - 1].matrix().inverse() * run.trajectory.poses[k].matrix();
    const Eigen::Matrix4d e = q.inverse() * p;
    t_err.push_back(e.block<3, 1>(0, 3).norm());
    r_err.push_back(angleDeg(e.block<3, 3>(0, 0)));
    EXPECT_NEAR(*run.frames[k].diff_m, t_err.back(), 1e-5);
  }
  std::vector<double> sorted = t_err;
  std::sort(sorted.begin(), sorted.end());
  const double median39 = sorted[19];  // 39 values: the middle one
  // The reference's rotations have 6 decimals: a rigid and a general inverse differ by ~1e-6.
  EXPECT_NEAR(run.rpe->translation_stats.median, median39, 1e-5);
  EXPECT_NEAR(run.rpe->translation_stats.max, sorted.back(), 1e-5);
  // The acceptance of the sequence layer: median <= 1 cm, no frame above 5 cm or 1 degree
  // (the reference itself aligns consecutive scans to about 2 cm).
  EXPECT_LE(median39, 0.010);
  EXPECT_LE(sorted.back(), 0.05);
  EXPECT_LE(*std::max_element(r_err.begin(), r_err.end()), 1.0);
}

TEST(OdometryRun, KittiPresetEqualsLidarOdometryScanByScan) {
  const std::string root = std::string(METRICMAP_DATA_DIR) + "/kitti_odometry_00";
  auto source = metricmap::openScanSource(root);
  metricmap::OdometryRunOptions options;
  options.profile = {false, false, false};  // the KITTI preset: the config's defaults
  options.frames = {0, 1, 2, 3};
  const metricmap::OdometryRun run = metricmap::runOdometry(*source, options);
  EXPECT_EQ(run.convention, "kitti camera 0");

  metricmap::LidarOdometry direct;
  const Eigen::Isometry3d tr = source->info().sensor_to_base;
  for (std::size_t k = 0; k < 4; ++k) {
    pcl::PointCloud<pcl::PointXYZ> scan;
    metricmap::loadCloud(root + "/sequences/00/velodyne/00000" + std::to_string(k) + ".bin", scan);
    const Eigen::Isometry3d pose = direct.registerFrame(scan).pose;
    const Eigen::Matrix4d camera = tr.matrix() * pose.matrix() * tr.matrix().inverse();
    EXPECT_TRUE(run.trajectory.poses[k].matrix().isApprox(camera, 1e-9)) << k;
  }
  ASSERT_TRUE(run.rpe.has_value());
  EXPECT_EQ(run.rpe->translation.size(), 3u);
}

TEST(OdometryRun, RefusesFramesOutOfOrderOrPastTheEnd) {
  auto source = metricmap::openScanSource(kBalm);
  metricmap::OdometryRunOptions options;
  options.frames = {0, 2, 1};
  EXPECT_THROW(metricmap::runOdometry(*source, options), std::invalid_argument);
  options.frames = {0, 40};
  EXPECT_THROW(metricmap::runOdometry(*source, options), metricmap::InputError);
}
