// Issue 24, class 8: a registration with too few pairs fails by a stated rule, naming the scan,
// instead of returning its starting pose or a pose fitted to a handful of points.
// refineScanPose (PCL ICP/GICP, `kitti --refine`): at least minRefinePairs(n) = max(20, n/10)
// pairs within the fine distance; LidarOdometry (`odometry`, `kitti --poses odometry`): at
// least kMinOdometryPairs (20) pairs. Above the minimums the results are unchanged.
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <pcl/common/transforms.h>

#include <gtest/gtest.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/registration/scan_registration.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

const KittiSequence kSeq{dataPath("kitti_odometry_00"), "00"};

Cloud velo(std::size_t frame) {
  Cloud scan;
  loadCloud(kSeq.scan(frame), scan);
  return scan;
}

// Sensor presets of the registration cloud: KITTI's HDL-64E band (3-40 m, above z = -1.3 m)
// and no band; points far apart stay one per cell, so the kept count is the band's count.
TEST(RegistrationCloud, SensorPresets) {
  Cloud scan;
  const float pts[][3] = {{2, 0, 0},   {5, 0, 0},    {0, 10, 0.5},  {45, 0, 0},
                          {0, 20, -2}, {-30, 0, -1}, {0, -39, 3.0}, {1, 1, 0}};
  for (const auto& p : pts) scan.push_back(pcl::PointXYZ(p[0], p[1], p[2]));
  const RegistrationCloudParams kitti = RegistrationCloudParams::kittiHdl64();
  EXPECT_EQ(registrationCloud(scan, kitti)->size(), 4u);  // 5 m, 10 m, 30 m at -1, 39 m
  EXPECT_EQ(registrationCloud(scan)->size(), 4u);         // the KITTI overload
  EXPECT_EQ(registrationCloud(scan, RegistrationCloudParams::unbanded())->size(), 8u);
  RegistrationCloudParams indoor;
  indoor.max_range = 25.0f;
  EXPECT_EQ(registrationCloud(scan, indoor)->size(), 5u);  // 2, 5, 10, 20 m and (1, 1)
  indoor.voxel = 0.0f;
  EXPECT_THROW(registrationCloud(scan, indoor), std::invalid_argument);
  indoor.voxel = 0.2f;
  indoor.max_range = 0.0f;
  EXPECT_THROW(registrationCloud(scan, indoor), std::invalid_argument);
}

/// Frame 0's registration cloud in the world (the target of frames 1-5).
Cloud::Ptr frameZeroTarget(const Eigen::Isometry3d& tr, const Eigen::Isometry3d& pose0) {
  auto target = std::make_shared<Cloud>();
  pcl::transformPointCloud(*registrationCloud(velo(0)), *target,
                           (pose0 * tr).matrix().cast<float>());
  return target;
}

std::string refineMessage(const Cloud::Ptr& source, const Cloud::Ptr& target,
                          const Eigen::Isometry3d& start, RefineMethod method) {
  RefineParams p;
  p.method = method;
  try {
    refineScanPose(source, target, start, p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RegistrationMinimums, RefinePairsRule) {
  EXPECT_EQ(minRefinePairs(0), 20u);
  EXPECT_EQ(minRefinePairs(200), 20u);
  EXPECT_EQ(minRefinePairs(201), 21u);
  EXPECT_EQ(minRefinePairs(5000), 500u);
}

TEST(RegistrationMinimums, RealFramesRegisterWellAboveTheMinimum) {
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  const auto poses = readKittiPoses(kSeq.poses(), 6);
  const Cloud::Ptr target = frameZeroTarget(tr, poses[0]);
  std::mt19937 rng(5);
  for (RefineMethod method : {RefineMethod::Icp, RefineMethod::Gicp}) {
    RefineParams p;
    p.method = method;
    for (std::size_t f = 1; f <= 5; ++f) {
      const Cloud::Ptr source = registrationCloud(velo(f));
      const Eigen::Isometry3d truth = poses[f] * tr;
      for (const Eigen::Isometry3d& start : {truth, perturbPose(truth, 0.5, 2.0, rng)}) {
        const RefineResult r = refineScanPose(source, target, start, p);
        const double share =
            static_cast<double>(r.correspondences) / static_cast<double>(source->size());
        EXPECT_GE(r.correspondences, 2 * minRefinePairs(source->size())) << "frame " << f;
        std::printf("%s frame %zu: %zu of %zu points paired (%.0f%%)\n",
                    method == RefineMethod::Icp ? "icp" : "gicp", f, r.correspondences,
                    source->size(), 100.0 * share);
      }
    }
  }
}

TEST(RegistrationMinimums, RefineFarFromTheTargetIsAnError) {
  // 30 m off: no target point within ICP's reach; PCL would return the starting pose.
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  const auto poses = readKittiPoses(kSeq.poses(), 2);
  const Cloud::Ptr target = frameZeroTarget(tr, poses[0]);
  const Cloud::Ptr source = registrationCloud(velo(1));
  Eigen::Isometry3d start = poses[1] * tr;
  start.translation() += Eigen::Vector3d(30.0, 0.0, 30.0);
  for (RefineMethod method : {RefineMethod::Icp, RefineMethod::Gicp}) {
    const std::string m = refineMessage(source, target, start, method);
    EXPECT_NE(m.find("registration paired"), std::string::npos) << m;
    EXPECT_NE(m.find("the pose cannot be trusted"), std::string::npos) << m;
  }
}

TEST(RegistrationMinimums, RefineOnAFewTargetPointsIsAnError) {
  // A target of 25 points: the pose would rest on a few dozen pairs of thousands of points.
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  const auto poses = readKittiPoses(kSeq.poses(), 2);
  const Cloud::Ptr full = frameZeroTarget(tr, poses[0]);
  auto target = std::make_shared<Cloud>();
  for (std::size_t i = 0; i < full->size() && target->size() < 25; i += full->size() / 25)
    target->push_back((*full)[i]);
  const Cloud::Ptr source = registrationCloud(velo(1));
  ASSERT_GT(source->size(), 1000u);
  const std::string m = refineMessage(source, target, poses[1] * tr, RefineMethod::Icp);
  EXPECT_NE(m.find("at least " + std::to_string(minRefinePairs(source->size())) + " needed"),
            std::string::npos)
      << m;
}

TEST(RegistrationMinimums, OdometryOnAFewDownsampledPointsIsAnErrorNamingTheFrame) {
  LidarOdometryConfig cfg;
  cfg.voxel_size = 100.0;  // 8 points of each KITTI scan left: 1 to 6 pairs
  LidarOdometry odo(cfg);
  odo.registerFrame(velo(0), {}, "000000.bin");
  try {
    odo.registerFrame(velo(1), {}, "000001.bin");
    FAIL() << "a pose fitted to a few points was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("000001.bin: the registration paired ", 0), 0u) << m;
    EXPECT_NE(m.find("at least 20 needed"), std::string::npos) << m;
  }
}

TEST(RegistrationMinimums, OdometryWithTheDefaultsPairsThousands) {
  LidarOdometry odo;
  for (std::size_t f = 0; f <= 3; ++f) {
    const OdometryResult r = odo.registerFrame(velo(f));
    if (f > 0) {
      EXPECT_GT(r.correspondences, 50 * kMinOdometryPairs) << "frame " << f;
    }
  }
}

}  // namespace metricmap
