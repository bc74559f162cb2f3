// ScanMapper, the mapping pipeline, used as a library user would: scans + poses in, map,
// cloud and poses out. Checked against a plain recount written here, PCL's transforms and the
// registration target's own definition.
#include <cmath>
#include <map>
#include <utility>

#include <pcl/common/transforms.h>

#include <gtest/gtest.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/sequence/scan_mapper.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
const KittiSequence kSeq{dataPath("kitti_odometry_00"), "00"};

struct Frames {
  std::vector<Cloud> scans;
  std::vector<Eigen::Isometry3d> poses;  // velodyne -> camera world
};

const Frames& frames() {
  static const Frames f = [] {
    Frames out;
    const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
    const auto poses = readKittiPoses(kSeq.poses(), 6);
    for (std::size_t i = 0; i < 6; ++i) {
      out.scans.emplace_back();
      loadCloud(kSeq.scan(i), out.scans.back());
      out.poses.push_back(kittiScanToWorld(poses[i], tr, KittiWorld::Camera));
    }
    return out;
  }();
  return f;
}

TEST(ScanMapper, MapEqualsAPlainRecountOfTheBandedScans) {
  ScanMapperConfig config;
  config.min_range = 2.5;
  config.max_range = 60.0;
  config.min_height = -1.0;  // up is -y in KITTI's camera world
  config.max_height = 2.0;
  config.map_resolution = 0.2;
  config.min_hits = 3;
  ScanMapper mapper(config);
  std::map<std::pair<long, long>, std::uint32_t> ref;  // (floor(x/r), floor(z/r)) -> hits
  std::uint64_t read = 0, mapped = 0;
  for (std::size_t i = 0; i < 6; ++i) {
    const FrameReport r = mapper.addScan(frames().scans[i], frames().poses[i]);
    EXPECT_EQ(r.index, i);
    EXPECT_FALSE(r.registered);
    EXPECT_TRUE(r.pose_used.isApprox(frames().poses[i]));
    read += r.points_read;
    mapped += r.points_mapped;
    const Eigen::Matrix4f m = frames().poses[i].matrix().cast<float>();
    for (const auto& p : frames().scans[i]) {
      const double range = p.getVector3fMap().norm();
      if (range < 2.5 || range > 60.0) continue;
      const Eigen::Vector3f w = (m * p.getVector4fMap()).head<3>();
      if (-w.y() < -1.0f || -w.y() > 2.0f) continue;
      ++ref[{std::lround(std::floor(w.x() / 0.2)), std::lround(std::floor(w.z() / 0.2))}];
    }
  }
  std::uint64_t total = 0;
  for (const Cloud& c : frames().scans) total += c.size();
  EXPECT_EQ(read, total);
  std::uint64_t ref_mapped = 0;
  std::size_t ref_occupied = 0;
  for (const auto& [cell, n] : ref) {
    ref_mapped += n;
    ref_occupied += n >= 3 ? 1 : 0;
  }
  // pcl::transformPointCloud and the loop above may round a handful of points to the other
  // side of a cell edge; the counts must agree to within a few points per million.
  EXPECT_NEAR(static_cast<double>(mapped), static_cast<double>(ref_mapped),
              1e-5 * static_cast<double>(ref_mapped) + 2);
  EXPECT_GT(mapped, total / 4);
  EXPECT_NEAR(static_cast<double>(mapper.map().cells()), static_cast<double>(ref.size()),
              1e-5 * static_cast<double>(ref.size()) + 2);
  EXPECT_NEAR(static_cast<double>(mapper.occupiedCells()), static_cast<double>(ref_occupied),
              1e-5 * static_cast<double>(ref_occupied) + 2);
  EXPECT_EQ(mapper.poses().size(), 6u);
}

TEST(ScanMapper, GlobalCloudIsTheTransformedRangeBand) {
  ScanMapperConfig config;
  config.min_range = 5.0;
  config.max_range = 30.0;
  ScanMapper mapper(config);
  Cloud expected;
  for (std::size_t i = 0; i < 2; ++i) {
    mapper.addScan(frames().scans[i], frames().poses[i]);
    Cloud band, world;
    for (const auto& p : frames().scans[i]) {
      const double r = p.getVector3fMap().norm();
      if (r >= 5.0 && r <= 30.0) band.push_back(p);
    }
    pcl::transformPointCloud(band, world, frames().poses[i].matrix().cast<float>());
    expected += world;
  }
  const Cloud global = mapper.globalCloud();
  ASSERT_EQ(global.size(), expected.size());
  for (std::size_t i = 0; i < global.size(); ++i) {
    ASSERT_EQ(global[i].getVector3fMap(), expected[i].getVector3fMap()) << i;
  }
}

TEST(ScanMapper, RegistrationTargetIsBuiltFromTheRangeBandedScanAtTheConfiguredVoxel) {
  for (double target_voxel : {0.2, 0.5}) {
    ScanMapperConfig config;
    config.max_range = 20.0;
    config.registration.enabled = true;
    config.registration.target_voxel = target_voxel;
    ScanMapper mapper(config);
    mapper.addScan(frames().scans[0], frames().poses[0]);
    const Cloud& target = mapper.registrationTarget();
    ASSERT_GT(target.size(), 100u);
    const Eigen::Vector3f origin = frames().poses[0].translation().cast<float>();
    for (const auto& p : target) {  // cell means of points within 20 m stay within 20 m
      ASSERT_LE((p.getVector3fMap() - origin).norm(), 20.0f + 1e-3f);
    }
    // The target of frame 0 is exactly its structure cloud averaged once more at the voxel.
    Cloud structure, expected;
    pcl::transformPointCloud(*registrationCloud(rangeBand(frames().scans[0], 0.0, 20.0)), structure,
                             frames().poses[0].matrix().cast<float>());
    expected = voxelAverage(structure, target_voxel);
    EXPECT_EQ(target.size(), expected.size()) << "voxel " << target_voxel;
  }
}

TEST(ScanMapper, RegistrationRecoversAPerturbedPose) {
  ScanMapperConfig config;
  config.min_range = 2.5;
  config.registration.enabled = true;
  config.registration.target = RegistrationTarget::First;
  ScanMapper mapper(config);
  mapper.addScan(frames().scans[0], frames().poses[0]);
  Eigen::Isometry3d moved = frames().poses[0];
  moved.translation() += Eigen::Vector3d(0.3, 0.0, -0.2);
  const FrameReport r = mapper.addScan(frames().scans[0], moved);  // the same scan again
  EXPECT_TRUE(r.registered);
  const PoseError e = poseError(frames().poses[0], r.pose_used);
  EXPECT_LT(e.translation, 0.02);
  EXPECT_LT(e.rotation_deg, 0.1);
  const TrajectoryError te = mapper.trajectoryError({frames().poses[0], frames().poses[0]});
  EXPECT_NEAR(te.given[1].translation, std::hypot(0.3, 0.2), 1e-6);  // Tr: orthonormal to 1e-7
  EXPECT_NEAR(te.ate_given, std::sqrt(0.13 / 2.0), 1e-6);
  EXPECT_LT(te.ate_used, 0.02);
  EXPECT_THROW(mapper.trajectoryError({frames().poses[0]}), std::invalid_argument);
}

TEST(ScanMapper, TooFewRegistrationPointsIsAnErrorNamingTheScan) {
  ScanMapperConfig config;
  config.max_range = 4.0;  // the registration cloud keeps 3-40 m: almost nothing is left
  config.registration.enabled = true;
  ScanMapper mapper(config);
  mapper.addScan(frames().scans[0], frames().poses[0]);
  try {
    mapper.addScan(frames().scans[1], frames().poses[1]);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scan 1"), std::string::npos) << e.what();
  }
}

TEST(ScanMapper, OdometryPosesNeedNoPoseFile) {
  ScanMapperConfig config;
  config.min_range = 2.5;
  EXPECT_THROW(ScanMapper(config).addScan(frames().scans[0]), std::logic_error);
  config.odometry = true;
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  config.odometry_origin = tr;  // the camera world of the first frame
  ScanMapper mapper(config);
  for (std::size_t i = 0; i < 6; ++i) mapper.addScan(frames().scans[i]);
  ASSERT_EQ(mapper.poses().size(), 6u);
  EXPECT_TRUE(mapper.poses()[0].isApprox(tr, 1e-9));
  for (std::size_t i = 1; i < 6; ++i) {
    // The scans' own motion (docs/KITTI.md): 0.67-0.74 m per frame, mostly forward (+z).
    const Eigen::Vector3d step =
        mapper.poses()[i].translation() - mapper.poses()[i - 1].translation();
    EXPECT_GT(step.norm(), 0.6) << i;
    EXPECT_LT(step.norm(), 0.8) << i;
    EXPECT_GT(step.z(), 0.95 * step.norm()) << i;
  }
  EXPECT_GT(mapper.occupiedCells(), 10000u);
}

TEST(ScanMapper, BadConfigurationsAreRefused) {
  auto bad = [](auto change) {
    ScanMapperConfig c;
    change(c);
    EXPECT_THROW(ScanMapper{c}, std::invalid_argument);
  };
  bad([](ScanMapperConfig& c) { c.min_range = -1; });
  bad([](ScanMapperConfig& c) { c.max_range = std::nan(""); });
  bad([](ScanMapperConfig& c) { c.max_range = 0; });
  bad([](ScanMapperConfig& c) { c.min_range = 10, c.max_range = 5; });
  bad([](ScanMapperConfig& c) { c.voxel = INFINITY; });
  bad([](ScanMapperConfig& c) { c.min_height = std::nan(""); });
  bad([](ScanMapperConfig& c) { c.min_height = 3, c.max_height = 1; });
  bad([](ScanMapperConfig& c) { c.map_resolution = 0; });
  bad([](ScanMapperConfig& c) { c.up = Eigen::Vector3f::Zero(); });
  bad([](ScanMapperConfig& c) { c.registration.target_voxel = -0.2; });
  bad([](ScanMapperConfig& c) { c.registration.cloud.voxel = 0.0f; });
  bad([](ScanMapperConfig& c) { c.registration.refine.max_iterations = 0; });
  EXPECT_THROW(parseRegistrationTarget("last"), std::invalid_argument);
  EXPECT_EQ(parseRegistrationTarget("previous"), RegistrationTarget::Previous);
}

}  // namespace
}  // namespace metricmap
