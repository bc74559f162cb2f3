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
#include "shared_data.h"

#include <pcl/common/transforms.h>
#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_plane.h>

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

namespace {

const std::string kNclt = std::string(METRICMAP_SHARED_DATA_DIR) + "/nclt_2013_01_10_keyframes";

// The largest plane among the points of `cloud` below `below` (z): PCL's RANSAC over planes of
// any orientation, refined by least squares.
Eigen::Vector3d floorNormal(const pcl::PointCloud<pcl::PointXYZ>& cloud, double below) {
  auto low = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : cloud)
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && p.z < below)
      low->push_back(p);
  auto model = std::make_shared<pcl::SampleConsensusModelPlane<pcl::PointXYZ>>(low, false);
  pcl::RandomSampleConsensus<pcl::PointXYZ> sac(model, 0.05);
  sac.setMaxIterations(1000);
  EXPECT_TRUE(sac.computeModel(0));
  pcl::Indices inliers;
  sac.getInliers(inliers);
  EXPECT_GT(inliers.size(), 200u);
  Eigen::VectorXf coeff(4), refined(4);
  sac.getModelCoefficients(coeff);
  model->optimizeModelCoefficients(inliers, coeff, refined);
  return Eigen::Vector3d(refined[0], refined[1], refined[2]).normalized();
}

}  // namespace

// The ground under a keyframe is the local terrain: on this campus it slopes by 1-3 deg against
// the reference's up (local ENU z), as the walls of the buildings do too (docs/ODOMETRY.md), so
// the ground's normal meets the reference within 3 deg, not 1; a wrong plane (a wall's foot, a
// ramp seen from its foot) would be off by far more.
TEST(LevelFrame, UpOfNcltKeyframesAgreesWithTheReferenceUpToTheTerrainSlope) {
  SKIP_WITHOUT_SHARED_DATA(kNclt);
  auto source = metricmap::openScanSource(kNclt);
  const auto& ref = source->info().reference.poses;
  std::vector<double> errors;
  for (std::size_t k : {0u, 200u, 400u, 600u, 800u, 1000u}) {
    const metricmap::Scan scan = source->scan(k);
    const metricmap::UpEstimate up = metricmap::estimateUp(metricmap::toPoints3d(scan.points));
    // The reference's up (local ENU z) in the keyframe's body frame.
    const Eigen::Vector3d ref_up = ref[k].linear().transpose() * Eigen::Vector3d::UnitZ();
    errors.push_back(std::acos(std::min(1.0, up.up.dot(ref_up))) * 180.0 / M_PI);
    EXPECT_LT(errors.back(), 12.0) << "keyframe " << k;
  }
  std::nth_element(errors.begin(), errors.begin() + 3, errors.end());
  EXPECT_LT(errors[3], 3.0);
  // The level world of a run: its z, seen from the first scan, is the reference's up there.
  metricmap::OdometryRunOptions options;
  options.config.threads = 1;
  options.frames = {0, 1};
  options.world = metricmap::WorldFrame::Level;
  const metricmap::OdometryRun run = metricmap::runOdometry(*source, options);
  ASSERT_EQ(run.world, metricmap::WorldFrame::Level);
  const Eigen::Vector3d world_z_in_first =
      run.level.linear().transpose() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d ref_up = ref[0].linear().transpose() * Eigen::Vector3d::UnitZ();
  EXPECT_LT(std::acos(std::min(1.0, world_z_in_first.dot(ref_up))) * 180.0 / M_PI, 3.0);
}

TEST(LevelFrame, TiltedHandCarriedScannerGivesALevelFloor) {
  SKIP_WITHOUT_SHARED_DATA(kBalm);
  auto source = metricmap::openScanSource(kBalm);
  metricmap::OdometryRunOptions options;
  options.world = metricmap::WorldFrame::Level;
  options.config.threads = 1;
  options.frames = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  const metricmap::OdometryRun run = metricmap::runOdometry(*source, options);
  ASSERT_EQ(run.world, metricmap::WorldFrame::Level);
  ASSERT_TRUE(run.up.has_value());
  // The scanner is held well off level: the first scan's floor is tilted in its frame.
  const double tilt = std::acos(run.up->up.z()) * 180.0 / M_PI;
  EXPECT_GT(tilt, 10.0);
  // The last scan, placed by the levelled trajectory: its floor's normal is the world's z.
  const std::size_t last = options.frames.back();
  pcl::PointCloud<pcl::PointXYZ> world;
  pcl::transformPointCloud(source->scan(last).points, world,
                           run.trajectory.poses.back().matrix().cast<float>());
  const Eigen::Vector3d n = floorNormal(world, -0.5 * run.up->height);
  EXPECT_LT(std::acos(std::abs(n.z())) * 180.0 / M_PI, 1.0);
  // The first-scan world keeps the first scan's frame: its first pose is the identity.
  options.world = metricmap::WorldFrame::FirstScan;
  options.frames = {0, 1};
  const metricmap::OdometryRun first = metricmap::runOdometry(*source, options);
  EXPECT_EQ(first.world, metricmap::WorldFrame::FirstScan);
  EXPECT_FALSE(first.up.has_value());
  EXPECT_TRUE(first.trajectory.poses[0].isApprox(Eigen::Isometry3d::Identity()));
  // The same run in the level world differs by the level rotation alone.
  EXPECT_TRUE(run.trajectory.poses[1].isApprox(run.level * first.trajectory.poses[1], 1e-9));
}

TEST(LevelFrame, EstimateUpRefusesBadArguments) {
  std::vector<Eigen::Vector3d> few(10, Eigen::Vector3d(1, 0, -1));
  EXPECT_THROW(metricmap::estimateUp(few, 0.0), std::invalid_argument);
  EXPECT_THROW(metricmap::estimateUp(few, 0.1, 90.0), std::invalid_argument);
  EXPECT_THROW(metricmap::estimateUp(few), metricmap::InputError);
}
