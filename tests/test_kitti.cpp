// KITTI readers against hand values, the transforms on known points, the 2D map against a
// brute-force recount, and the ground-truth alignment of frames 1-5 with frame 0.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <pcl/common/transforms.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <gtest/gtest.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/mapping/occupancy_map_2d.h"
#include "metricmap/registration/scan_registration.h"
#include "scratch_files.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
const KittiSequence kSeq{dataPath("kitti_odometry_00"), "00"};

/// Files in a directory of this process, removed when it exits.
std::string writeTemp(const std::string& name, const std::string& text) {
  static const test_support::ScratchDir dir("metricmap_kitti_");
  return dir.write(name, text);
}

}  // namespace

TEST(Kitti, CalibAndPosesAgainstHandValues) {
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  EXPECT_DOUBLE_EQ(tr(0, 0), 4.276802385584e-04);
  EXPECT_DOUBLE_EQ(tr(0, 1), -9.999672484946e-01);
  EXPECT_DOUBLE_EQ(tr(0, 3), -1.198459927713e-02);
  EXPECT_DOUBLE_EQ(tr(2, 3), -2.921968648686e-01);
  const auto poses = readKittiPoses(kSeq.poses(), 6);
  ASSERT_EQ(poses.size(), 6u);
  EXPECT_DOUBLE_EQ(poses[1](0, 0), 9.999978e-01);
  EXPECT_DOUBLE_EQ(poses[1](0, 3), -4.690294e-02);
  EXPECT_DOUBLE_EQ(poses[1](2, 3), 8.586941e-01);
  EXPECT_EQ(kSeq.scan(5), dataPath("kitti_odometry_00") + "/sequences/00/velodyne/000005.bin");
}

TEST(Kitti, FrameListsAndBadFiles) {
  EXPECT_EQ(parseFrameList("0-3,7"), (std::vector<std::size_t>{0, 1, 2, 3, 7}));
  EXPECT_THROW(parseFrameList("3-1"), std::invalid_argument);
  EXPECT_THROW(parseFrameList("a"), std::invalid_argument);
  EXPECT_THROW(parseFrameList(""), std::invalid_argument);
  EXPECT_THROW(readKittiCalibTr(writeTemp("calib_no_tr.txt", "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n")),
               InputError);
  EXPECT_THROW(readKittiCalibTr(writeTemp("calib_short.txt", "Tr: 1 0 0\n")), InputError);
  EXPECT_THROW(readKittiPoses(kSeq.poses(), 5000), InputError);  // the file has 4541 lines
  EXPECT_THROW(readKittiPoses(writeTemp("poses_nan.txt", "1 0 0 0 0 1 0 0 0 0 1 nan\n"), 1),
               InputError);
  EXPECT_THROW(readKittiCalibTr("/no/such/calib.txt"), InputError);
}

TEST(Kitti, TransformsOfKnownPoints) {
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  // A point 10 m ahead of the velodyne is about 10 m along the camera's z (forward).
  const Eigen::Vector3d ahead =
      kittiScanToWorld(identity, tr, KittiWorld::Camera) * Eigen::Vector3d(10, 0, 0);
  EXPECT_NEAR(ahead.z(), 10.0 * 9.999738645903e-01 - 2.921968648686e-01, 1e-9);
  EXPECT_NEAR(ahead.x(), 10.0 * 4.276802385584e-04 - 1.198459927713e-02, 1e-9);
  // The velodyne world of frame 0 is the velodyne frame itself.
  const Eigen::Vector3d p(3, -2, 1);
  EXPECT_LT((kittiScanToWorld(identity, tr, KittiWorld::Velodyne) * p - p).norm(), 1e-12);
  // With frame 1's pose: velodyne world = Tr^-1 P1 Tr, camera world = P1 Tr.
  const auto poses = readKittiPoses(kSeq.poses(), 2);
  const Eigen::Vector3d cam = kittiScanToWorld(poses[1], tr, KittiWorld::Camera) * p;
  const Eigen::Vector3d velo = kittiScanToWorld(poses[1], tr, KittiWorld::Velodyne) * p;
  EXPECT_LT((tr * velo - cam).norm(), 1e-9);
}

TEST(Kitti, MapMatchesBruteForceRecount) {
  Cloud scan;
  loadCloud(kSeq.scan(0), scan);
  for (MapPlane plane : {MapPlane::XZ, MapPlane::XY, MapPlane::YZ}) {
    OccupancyMap2D map(0.25, plane);
    map.add(scan);
    const MapImage img = map.image();
    const int a = plane == MapPlane::YZ ? 1 : 0, b = plane == MapPlane::XY ? 1 : 2;
    std::map<std::pair<long, long>, std::uint32_t> ref;
    for (const auto& p : scan) {
      const float* v = &p.x;
      ++ref[{static_cast<long>(std::floor(v[a] / 0.25)),
             static_cast<long>(std::floor(v[b] / 0.25))}];
    }
    EXPECT_EQ(map.cells(), ref.size());
    std::uint64_t total = 0;
    for (const auto& [cell, n] : ref) {
      const int col = static_cast<int>(std::lround(cell.first - img.origin_x / 0.25));
      const int row =
          img.height - 1 - static_cast<int>(std::lround(cell.second - img.origin_y / 0.25));
      ASSERT_GE(col, 0);
      ASSERT_GE(row, 0);
      ASSERT_EQ(img.at(col, row), n);
      total += n;
    }
    EXPECT_EQ(total, scan.size());
  }
}

TEST(Kitti, GroundTruthPosesAlignFramesWithFrameZero) {
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  const auto poses = readKittiPoses(kSeq.poses(), 6);
  auto nonGround = [&](std::size_t f, const Eigen::Isometry3d& pose) {
    Cloud scan, kept;
    loadCloud(kSeq.scan(f), scan);
    for (const auto& p : scan) {
      const float r = p.getVector3fMap().norm();
      if (r > 3.0f && r < 40.0f && p.z > -1.3f) kept.push_back(p);
    }
    Cloud world;
    pcl::transformPointCloud(kept, world, (pose * tr).matrix().cast<float>());
    return world;
  };
  auto reference = std::make_shared<Cloud>(nonGround(0, poses[0]));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(reference);
  auto medianDistance = [&](const Cloud& c) {
    std::vector<float> d;
    pcl::Indices idx(1);
    std::vector<float> sq(1);
    for (std::size_t i = 0; i < c.size(); i += 7) {
      tree.nearestKSearch(c[i], 1, idx, sq);
      d.push_back(std::sqrt(sq[0]));
    }
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    return d[d.size() / 2];
  };
  for (std::size_t f = 1; f <= 5; ++f) {
    const float with_truth = medianDistance(nonGround(f, poses[f]));
    const float with_identity = medianDistance(nonGround(f, poses[0]));
    EXPECT_LT(with_truth, 0.2f) << "frame " << f;
    if (f >= 3) {
      EXPECT_GT(with_identity, 0.2f) << "frame " << f;  // moved ~2.6 m by frame 3
    }
    EXPECT_LT(with_truth, with_identity) << "frame " << f;
  }
}

}  // namespace metricmap

namespace metricmap {

TEST(KittiRegistration, PerturbationHasTheAskedMagnitude) {
  std::mt19937 rng(3);
  const Eigen::Isometry3d pose =
      Eigen::Translation3d(1, 2, 3) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY());
  for (int i = 0; i < 20; ++i) {
    const PoseError e = poseError(pose, perturbPose(pose, 0.5, 2.0, rng));
    EXPECT_NEAR(e.translation, 0.5, 1e-9);
    EXPECT_NEAR(e.rotation_deg, 2.0, 1e-6);
  }
}

TEST(KittiRegistration, IcpAndGicpRecoverAKnownTransformOfARealScan) {
  // Scan 000000 moved by a known transform is the target; starting 0.5 m and 2 degrees off,
  // the refinement must find the transform again.
  auto scan = std::make_shared<Cloud>();
  Cloud raw;
  loadCloud(kSeq.scan(0), raw);
  for (std::size_t i = 0; i < raw.size(); i += 4) {
    const float r = raw[i].getVector3fMap().norm();
    if (r > 2.5f && r < 50.0f) scan->push_back(raw[i]);
  }
  const Eigen::Isometry3d truth =
      Eigen::Translation3d(3.0, -1.0, 0.2) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ());
  auto target = std::make_shared<Cloud>();
  pcl::transformPointCloud(*scan, *target, truth.matrix().cast<float>());
  std::mt19937 rng(7);
  for (RefineMethod method : {RefineMethod::Icp, RefineMethod::Gicp}) {
    RefineParams p;
    p.method = method;
    const RefineResult r = refineScanPose(scan, target, perturbPose(truth, 0.5, 2.0, rng), p);
    const PoseError e = poseError(truth, r.scan_to_world);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(e.translation, 0.02) << (method == RefineMethod::Icp ? "icp" : "gicp");
    EXPECT_LT(e.rotation_deg, 0.05) << (method == RefineMethod::Icp ? "icp" : "gicp");
  }
}

}  // namespace metricmap

namespace metricmap {

// Acceptance 2's question (does ICP correct a 0.5 m / 2 degree pose error?) asked of what the
// scans themselves say: every frame 1-5, registered to frame 0 from its ground-truth pose
// perturbed by 0.5 m and 2 degrees, must land within 0.1 m and 0.3 degrees of the pose the same
// registration reaches from the unperturbed ground truth. (The ground truth itself is not the
// oracle here: for frames 0-14 of sequence 00 it is a constant-velocity track that the scans
// contradict, see docs/KITTI.md and the next test.)
TEST(KittiRegistration, PerturbedPosesConvergeToTheUnperturbedSolution) {
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  const auto poses = readKittiPoses(kSeq.poses(), 6);
  auto velo = [&](std::size_t f) {
    Cloud scan;
    loadCloud(kSeq.scan(f), scan);
    return scan;
  };
  auto target = std::make_shared<Cloud>();
  pcl::transformPointCloud(*registrationCloud(velo(0)), *target,
                           (poses[0] * tr).matrix().cast<float>());
  std::mt19937 rng(11);
  for (RefineMethod method : {RefineMethod::Icp, RefineMethod::Gicp}) {
    RefineParams p;
    p.method = method;
    for (std::size_t f = 1; f <= 5; ++f) {
      const auto source = registrationCloud(velo(f));
      const Eigen::Isometry3d truth = poses[f] * tr;
      const RefineResult from_truth = refineScanPose(source, target, truth, p);
      const RefineResult from_noise =
          refineScanPose(source, target, perturbPose(truth, 0.5, 2.0, rng), p);
      const PoseError e = poseError(from_truth.scan_to_world, from_noise.scan_to_world);
      const char* name = method == RefineMethod::Icp ? "icp" : "gicp";
      EXPECT_TRUE(from_noise.converged) << name << " frame " << f;
      EXPECT_LT(e.translation, 0.1) << name << " frame " << f;
      EXPECT_LT(e.rotation_deg, 0.3) << name << " frame " << f;
    }
  }
}

}  // namespace metricmap

namespace metricmap {

// The finding that keeps acceptance 2 of the KITTI issue open, kept true by a test: the
// ground truth of sequence 00 moves exactly 0.860 m per frame for frames 0-14 (a
// constant-velocity track; from frame 15 on it varies), while the scans fit each other best at
// about 0.8 of that motion. The scan check is a plain sweep along the ground-truth relative
// motion, independent of the registration code: the median nearest-neighbour distance of
// scan 1's structure points to scan 0's.
TEST(KittiData, GroundTruthOfFrames0To14IsConstantVelocityAndTheScansDisagree) {
  const auto poses = readKittiPoses(kSeq.poses(), 41);
  for (std::size_t f = 1; f < 41; ++f) {
    const double step = (poses[f].translation() - poses[f - 1].translation()).norm();
    if (f <= 14) {
      EXPECT_NEAR(step, 0.860, 0.002) << "frame " << f;
    }
    if (f >= 20) {
      EXPECT_GT(step, 0.89) << "frame " << f;  // the car speeds up, 0.90 -> 1.06 m
    }
  }
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  Cloud s0, s1;
  loadCloud(kSeq.scan(0), s0);
  loadCloud(kSeq.scan(1), s1);
  auto structure = [](const Cloud& c) {
    auto out = std::make_shared<Cloud>();
    for (const auto& p : c) {
      const float r = std::hypot(p.x, p.y);
      if (r > 3.0f && r < 40.0f && p.z > -1.3f) out->push_back(p);
    }
    return out;
  };
  const auto a = structure(s0), b = structure(s1);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(a);
  const Eigen::Isometry3d rel = tr.inverse() * poses[0].inverse() * poses[1] * tr;
  double best_scale = 0.0, best = 1e9;
  for (int i = 50; i <= 120; i += 2) {
    Eigen::Isometry3d t = rel;
    t.translation() *= i / 100.0;
    Cloud moved;
    pcl::transformPointCloud(*b, moved, t.matrix().cast<float>());
    std::vector<float> d;
    pcl::Indices idx(1);
    std::vector<float> sq(1);
    for (std::size_t k = 0; k < moved.size(); k += 3) {
      tree.nearestKSearch(moved[k], 1, idx, sq);
      d.push_back(sq[0]);
    }
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    if (d[d.size() / 2] < best) {
      best = d[d.size() / 2];
      best_scale = i / 100.0;
    }
  }
  EXPECT_GT(best_scale, 0.70);
  EXPECT_LT(best_scale, 0.90);  // 0.86 m by the poses, about 0.68 m by the scans
}

TEST(Kitti, MapSizeLimitsAreCapacityErrors) {
  Cloud far;
  far.push_back(pcl::PointXYZ(-1.9e8f, 0, 0));
  far.push_back(pcl::PointXYZ(1.9e8f, 0, 1));
  OccupancyMap2D map(0.1, MapPlane::XZ);
  map.add(far);  // 3.8e9 cells apart: each index fits, the image does not
  EXPECT_THROW(map.image(), CapacityError);
  OccupancyMap2D fine(1e-3, MapPlane::XZ);
  EXPECT_THROW(fine.add(far), CapacityError);  // an index beyond 2e9
  Cloud scan;
  loadCloud(kSeq.scan(0), scan);
  OccupancyMap2D dense(0.0055, MapPlane::XY);  // tens of thousands of pixels each way
  dense.add(scan);
  try {
    dense.image();
    FAIL() << "expected CapacityError";
  } catch (const CapacityError& e) {
    EXPECT_NE(std::string(e.what()).find("coarser"), std::string::npos) << e.what();
  }
  OccupancyMap2D coarse(0.5, MapPlane::XY);
  coarse.add(scan);
  EXPECT_GT(coarse.image().width, 100);
}

TEST(Kitti, FrameListsAreBoundedBeforeAllocating) {
  EXPECT_THROW(parseFrameList("0-999999999"), std::invalid_argument);
  EXPECT_THROW(parseFrameList("0-5,7-10", 9), std::invalid_argument);
  EXPECT_EQ(parseFrameList("0-5,7-9", 9).size(), 9u);
  EXPECT_EQ(parseFrameList("4,2"), (std::vector<std::size_t>{4, 2}));
}

TEST(Kitti, PoseFilesRoundTrip) {
  const auto poses = readKittiPoses(kSeq.poses(), 6);
  const std::string path = writeTemp("poses_round_trip.txt", formatKittiPoses(poses));
  const auto back = readKittiPoses(path, 6);
  const Eigen::Isometry3d tr = readKittiCalibTr(kSeq.calib());
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_LT((back[i].matrix() - poses[i].matrix()).cwiseAbs().maxCoeff(), 1e-8);
    for (KittiWorld w : {KittiWorld::Camera, KittiWorld::Velodyne}) {
      const Eigen::Isometry3d again = kittiPoseOfScan(kittiScanToWorld(poses[i], tr, w), tr, w);
      const Eigen::Isometry3d expected =
          w == KittiWorld::Camera ? poses[i] : kittiScanToWorld(poses[i], tr, w);
      EXPECT_LT((again.matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-6);
    }
  }
}

}  // namespace metricmap
