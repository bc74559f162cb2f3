// LidarOdometry against PCL's GeneralizedIterativeClosestPoint run pairwise on the bundled KITTI
// frames, against known rigid motions of a real scan, reversed order, thinned scans, bad scans;
// its parts (SE(3) maps, voxel map, threshold, deskew, degenerate directions) against plain
// references.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <tuple>

#include <pcl/filters/voxel_grid.h>
#include <pcl/registration/gicp.h>

#include <gtest/gtest.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/registration/adaptive_threshold.h"
#include "metricmap/registration/deskew.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/registration/point_to_point_icp.h"
#include "metricmap/registration/scan_registration.h"
#include "metricmap/registration/se3.h"
#include "metricmap/registration/voxel_downsample.h"
#include "metricmap/registration/voxel_hash_map.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Points = std::vector<Eigen::Vector3d>;
const KittiSequence kSeq{dataPath("kitti_odometry_00"), "00"};
constexpr double kDeg = 180.0 / M_PI;

const std::vector<Points>& kittiScans() {
  static const std::vector<Points> scans = [] {
    std::vector<Points> s;
    for (std::size_t f = 0; f <= 5; ++f) {
      Cloud c;
      loadCloud(kSeq.scan(f), c);
      s.push_back(toPoints3d(c));
    }
    return s;
  }();
  return scans;
}

Eigen::Isometry3d relative(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  Eigen::Isometry3d d;
  d.matrix() = a.matrix().inverse() * b.matrix();
  return d;
}

// The oracle: pcl::GeneralizedIterativeClosestPoint from the identity, scan `source` onto scan
// `target` (both 3-80 m, 0.4 m voxels), correspondences within 1.5 m then 0.5 m. Returns
// target <- source, i.e. the motion from the target's sensor pose to the source's.
Eigen::Isometry3d gicpMotion(const Points& target, const Points& source) {
  auto prepare = [](const Points& pts) {
    auto c = std::make_shared<Cloud>();
    for (const auto& p : pts) {
      const double r = p.norm();
      if (r > 3.0 && r < 80.0)
        c->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
    }
    pcl::VoxelGrid<pcl::PointXYZ> vg;
    vg.setLeafSize(0.4f, 0.4f, 0.4f);
    vg.setInputCloud(c);
    auto out = std::make_shared<Cloud>();
    vg.filter(*out);
    return out;
  };
  pcl::GeneralizedIterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> gicp;
  gicp.setInputSource(prepare(source));
  gicp.setInputTarget(prepare(target));
  gicp.setMaximumIterations(100);
  gicp.setTransformationEpsilon(1e-12);
  gicp.setEuclideanFitnessEpsilon(1e-12);
  Eigen::Matrix4f guess = Eigen::Matrix4f::Identity();
  Cloud aligned;
  for (double d : {1.5, 0.5}) {
    gicp.setMaxCorrespondenceDistance(d);
    gicp.align(aligned, guess);
    guess = gicp.getFinalTransformation();
  }
  EXPECT_TRUE(gicp.hasConverged());
  Eigen::Isometry3d t;
  t.matrix() = guess.cast<double>();
  return t;
}

Points transformed(const Points& pts, const Eigen::Isometry3d& t) {
  Points out(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) out[i] = t * pts[i];
  return out;
}

std::vector<Eigen::Isometry3d> runOdometry(const std::vector<std::size_t>& order,
                                           const LidarOdometryConfig& cfg = {}) {
  LidarOdometry odo(cfg);
  for (std::size_t f : order) odo.registerFrame(kittiScans()[f]);
  return odo.poses();
}

}  // namespace

TEST(LidarOdometryParts, Se3ExpLogAgainstAngleAxis) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    Vector6d xi;
    for (int k = 0; k < 6; ++k) xi(k) = u(rng) * (k < 3 ? 5.0 : 1.5);
    const Eigen::Isometry3d t = se3Exp(xi);
    const double angle = xi.tail<3>().norm();
    // Rotation: Eigen's angle-axis. Translation: integral of the screw motion, by quadrature.
    EXPECT_TRUE(t.linear().isApprox(
        Eigen::AngleAxisd(angle, xi.tail<3>() / angle).toRotationMatrix(), 1e-12));
    Eigen::Vector3d integral = Eigen::Vector3d::Zero();
    const int n = 2000;
    for (int s = 0; s < n; ++s) {
      const double a = (s + 0.5) / n * angle;
      integral += Eigen::AngleAxisd(a, xi.tail<3>() / angle).toRotationMatrix() * xi.head<3>() / n;
    }
    EXPECT_LT((t.translation() - integral).norm(), 1e-5);
    EXPECT_LT((se3Log(t) - xi).norm(), 1e-9);
  }
  EXPECT_LT((se3Exp(Vector6d::Zero()).matrix() - Eigen::Matrix4d::Identity()).norm(), 1e-15);
}

TEST(LidarOdometryParts, VoxelMapNearestAgainstBruteForce) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  Points pts(3000);
  for (auto& p : pts) p = Eigen::Vector3d(u(rng), u(rng), u(rng) * 0.2);
  VoxelHashMap map(1.0, 4);
  map.add(pts);
  const Points held = map.cloud();
  EXPECT_EQ(held.size(), map.points());
  // At most 4 per voxel, and a point is dropped only when its voxel already had 4.
  std::map<std::tuple<int, int, int>, int> per_voxel;
  for (const auto& p : pts) {
    ++per_voxel[{int(std::floor(p.x())), int(std::floor(p.y())), int(std::floor(p.z()))}];
  }
  std::size_t expected = 0;
  for (const auto& kv : per_voxel) expected += std::min(kv.second, 4);
  EXPECT_EQ(map.points(), expected);
  EXPECT_EQ(map.voxels(), per_voxel.size());
  // The plain reference: the first held point at the smallest distance.
  auto bruteNearest = [&held](const Eigen::Vector3d& q, Eigen::Vector3d& arg) {
    double best = 1e9;
    for (const auto& h : held) {
      if ((h - q).norm() < best) {
        best = (h - q).norm();
        arg = h;
      }
    }
    return best;
  };
  VoxelHashMap::Neighbourhood hood;
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d q(u(rng), u(rng), u(rng) * 0.2);
    Eigen::Vector3d arg;
    const double best = bruteNearest(q, arg);
    Eigen::Vector3d got;
    // Within one voxel the 27-voxel search is exact.
    const bool found = map.nearest(q, 0.99, got);
    EXPECT_EQ(found, best < 0.99);
    if (found) {
      EXPECT_EQ(got, arg);
    }
    // The cached form, its neighbourhood reused by nearby queries (same voxel or not), as ICP
    // reuses it between steps: the same answers.
    for (int j = 0; j < 4; ++j) {
      const Eigen::Vector3d qj = q + Eigen::Vector3d(0.3 * j, -0.2 * j, 0.05 * j);
      Eigen::Vector3d arg_j;
      const double best_j = bruteNearest(qj, arg_j);
      Eigen::Vector3d got_j;
      const bool found_j = map.nearestCached(qj, 0.99, hood, got_j);
      EXPECT_EQ(found_j, best_j < 0.99);
      if (found_j) {
        EXPECT_EQ(got_j, arg_j);
      }
    }
  }
  map.removeFar(Eigen::Vector3d::Zero(), 5.0);
  for (const auto& h : map.cloud()) EXPECT_LT(h.norm(), 5.0 + 2.0 * std::sqrt(3.0));
  EXPECT_LT(map.points(), expected);
  EXPECT_THROW(VoxelHashMap(0.0, 4), std::invalid_argument);
  EXPECT_THROW(VoxelHashMap(1.0, 0), std::invalid_argument);
}

TEST(LidarOdometryParts, VoxelMapAfterRemovalAgainstBruteForce) {
  // Voxels dropped from the middle of the numbering, then more added: every query still finds
  // what a search over the held points finds, and each voxel number holds its answer.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  VoxelHashMap map(1.0, 3);
  auto addRandom = [&](int n) {
    Points pts(static_cast<std::size_t>(n));
    for (auto& p : pts) p = Eigen::Vector3d(u(rng), u(rng), 0.1 * u(rng));
    map.add(pts);
  };
  addRandom(8000);
  const std::size_t before = map.voxels();
  map.removeFar(Eigen::Vector3d(5.0, 0.0, 0.0), 9.0);
  EXPECT_LT(map.voxels(), before);
  addRandom(3000);
  const Points held = map.cloud();
  EXPECT_EQ(held.size(), map.points());
  VoxelHashMap::Neighbourhood hood;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d q(u(rng), u(rng), 0.1 * u(rng));
    double best = 0.99;
    const Eigen::Vector3d* arg = nullptr;
    for (const auto& h : held) {
      if ((h - q).norm() < best) {
        best = (h - q).norm();
        arg = &h;
      }
    }
    Eigen::Vector3d got;
    std::int32_t v = -1;
    const bool found = map.nearestCached(q, 0.99, hood, got, &v);
    ASSERT_EQ(found, arg != nullptr) << i;
    if (!found) continue;
    EXPECT_EQ(got, *arg);
    ASSERT_GE(v, 0);
    bool held_there = false;
    for (int k = 0; k < map.voxelSize(v); ++k) held_there |= map.voxelPoint(v, k) == got;
    EXPECT_TRUE(held_there);
    EXPECT_EQ(map.voxelOfPoint(got), v);
  }
  map.clear();
  EXPECT_TRUE(map.empty());
  EXPECT_EQ(map.points(), 0u);
  Eigen::Vector3d got;
  EXPECT_FALSE(map.nearest(Eigen::Vector3d::Zero(), 10.0, got));
  EXPECT_THROW(VoxelHashMap(1.0, VoxelHashMap::kMaxPointsPerVoxel + 1), std::invalid_argument);
}

TEST(LidarOdometryParts, VoxelMapNearestFarFromTheOriginWithAnInexactVoxel) {
  // 0.7 m voxels ~700 km out: p / voxel rounds, and the faces' distances with it. A query a
  // few centimetres inside a corner of its voxel, a point b on the corner across it, and a
  // point a in the query's own voxel mirrored from b and then moved one ulp farther in x and
  // one nearer in y: b is nearer by ~1e-12 m². Skipping b's voxel must not lose it.
  const double voxel = 0.7, inv = 1.0 / voxel;
  auto upperFace = [&](double c) {  // the first coordinate of cell c + 1, as the map computes it
    double face = (c + 1.0) * voxel;
    while (std::floor(face * inv) > c) face = std::nextafter(face, -1e300);
    while (std::floor(face * inv) <= c) face = std::nextafter(face, 1e300);
    return face;
  };
  const Eigen::Vector3d r(0.03, 0.025, 0.02);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cell(900000, 1040000);
  int wrong = 0, trials = 0;
  VoxelHashMap map(voxel, 4);
  for (int t = 0; t < 2000; ++t) {
    Eigen::Vector3d b, q;
    for (int k = 0; k < 3; ++k) {
      b[k] = upperFace(cell(rng));
      q[k] = b[k] - r[k];
    }
    Eigen::Vector3d a = q - (b - q);
    a.x() = std::nextafter(a.x(), -1e300);
    a.y() = std::nextafter(a.y(), 1e300);
    if (!((b - q).squaredNorm() < (a - q).squaredNorm())) continue;
    ++trials;
    map.clear();
    map.add({a, b});
    Eigen::Vector3d got;
    wrong += !map.nearest(q, 0.5, got) || got != b;
  }
  EXPECT_EQ(wrong, 0) << "of " << trials;
  EXPECT_GT(trials, 1500);
}

TEST(LidarOdometryParts, DownsampleInRangeIsTheWindowThenTheDownsampling) {
  // The plain reference: copy the finite points within the window, downsample the copy, map
  // the kept indices back. Both input forms (double vectors, a PCL cloud) must give it.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-60.0, 60.0);
  Cloud cloud;
  for (int i = 0; i < 30000; ++i) {
    pcl::PointXYZ p(static_cast<float>(u(rng)), static_cast<float>(u(rng)),
                    static_cast<float>(0.05 * u(rng)));
    if (i % 97 == 0) p.x = std::numeric_limits<float>::quiet_NaN();
    if (i % 89 == 0) p.z = std::numeric_limits<float>::infinity();
    cloud.push_back(p);
    if (i % 3 == 0) cloud.push_back(p);  // runs of repeated points, as scans have
  }
  const Points pts = toPoints3d(cloud);
  const double r_min = 3.0, r_max = 50.0;
  Points window;
  std::vector<int> window_index;
  std::size_t finite = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!pts[i].allFinite()) continue;
    ++finite;
    const double r = pts[i].norm();
    if (r < r_min || r > r_max) continue;
    window.push_back(pts[i]);
    window_index.push_back(static_cast<int>(i));
  }
  for (const double voxel : {0.5, 1.5}) {
    std::vector<int> ref_kept;
    const Points ref = voxelDownsample(window, voxel, &ref_kept);
    for (int& k : ref_kept) k = window_index[static_cast<std::size_t>(k)];
    Points out{{1, 2, 3}};  // cleared first
    std::vector<int> kept{42};
    const RangeWindowCounts a = downsampleInRange(pts, r_min, r_max, voxel, out, &kept);
    EXPECT_EQ(out, ref);
    EXPECT_EQ(kept, ref_kept);
    EXPECT_EQ(a.finite, finite);
    EXPECT_EQ(a.in_range, window.size());
    Points out_cloud;
    std::vector<int> kept_cloud;
    const RangeWindowCounts b =
        downsampleInRange(cloud, r_min, r_max, voxel, out_cloud, &kept_cloud);
    EXPECT_EQ(out_cloud, ref);
    EXPECT_EQ(kept_cloud, ref_kept);
    EXPECT_EQ(b.finite, finite);
    EXPECT_EQ(b.in_range, window.size());
  }
  Points out;
  EXPECT_THROW(downsampleInRange(pts, r_min, r_max, 0.0, out), std::invalid_argument);
  EXPECT_THROW(voxelDownsample(out, 1.0, out), std::invalid_argument);
}

TEST(LidarOdometryParts, DownsampleKeepsFirstPointPerVoxel) {
  const Points pts{{0.1, 0.1, 0.1}, {0.4, 0.2, 0.3}, {1.2, 0, 0}, {-0.1, 0, 0}, {1.9, 0.5, 0.5}};
  std::vector<int> kept;
  const Points out = voxelDownsample(pts, 1.0, &kept);
  EXPECT_EQ(kept, (std::vector<int>{0, 2, 3}));
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1], pts[2]);
  EXPECT_THROW(voxelDownsample(pts, -1.0), std::invalid_argument);
  EXPECT_THROW(voxelDownsample({{1e9, 0, 0}}, 0.1), CapacityError);
}

TEST(LidarOdometryParts, DownsampleAgainstASetOnManyVoxels) {
  // Far more distinct voxels than the first table holds, repeated points and negative cells.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-30.0, 30.0);
  Points pts;
  for (int i = 0; i < 40000; ++i) pts.emplace_back(u(rng), u(rng), 0.1 * u(rng));
  for (int i = 0; i < 10000; ++i) pts.push_back(pts[static_cast<std::size_t>(i) * 3]);
  for (const double voxel : {0.05, 0.5, 1.5}) {
    std::set<std::tuple<long, long, long>> seen;
    std::vector<int> expected;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const auto key = std::make_tuple(std::lround(std::floor(pts[i].x() / voxel)),
                                       std::lround(std::floor(pts[i].y() / voxel)),
                                       std::lround(std::floor(pts[i].z() / voxel)));
      if (seen.insert(key).second) expected.push_back(static_cast<int>(i));
    }
    std::vector<int> kept;
    const Points out = voxelDownsample(pts, voxel, &kept);
    EXPECT_EQ(kept, expected) << "voxel " << voxel;
    ASSERT_EQ(out.size(), expected.size());
    EXPECT_GT(expected.size(), voxel < 0.1 ? 30000u : 100u);
  }
}

TEST(LidarOdometryParts, AdaptiveThresholdHandValues) {
  AdaptiveThreshold th(2.0, 0.3, 0.1, 100.0);
  EXPECT_DOUBLE_EQ(th.threshold(), 6.0);
  Eigen::Isometry3d d = Eigen::Isometry3d::Identity();
  d.translation() = Eigen::Vector3d(0.3, 0.4, 0.0);  // 0.5 m
  th.update(d);
  EXPECT_NEAR(th.threshold(), 1.5, 1e-12);
  d.translation().setZero();
  d.linear() = Eigen::AngleAxisd(0.002, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  // 2 * 100 * sin(0.001) = 0.2 m; rms of 0.5 and 0.2.
  th.update(d);
  EXPECT_NEAR(th.threshold(),
              3.0 * std::sqrt((0.25 + 4.0 * 1e4 * std::pow(std::sin(0.001), 2)) / 2), 1e-9);
  AdaptiveThreshold still(2.0, 0.3, 0.1, 100.0);
  for (int i = 0; i < 10; ++i) still.update(Eigen::Isometry3d::Identity());
  EXPECT_NEAR(still.threshold(), 0.3, 1e-12);  // 3 x min_deviation, and the floor
}

TEST(LidarOdometryParts, DeskewMovesEachPointByItsShareOfTheMotion) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
  const Points pts{{10, 0, 0}, {0, 10, 0}, {-10, 0, 0}};
  const std::vector<double> t{0.0, 0.5, 1.0};
  const Points out = deskewScan(pts, t, motion);
  EXPECT_LT((out[0] - Eigen::Vector3d(9.5, 0, 0)).norm(), 1e-12);
  EXPECT_LT((out[1] - pts[1]).norm(), 1e-12);
  EXPECT_LT((out[2] - Eigen::Vector3d(-9.5, 0, 0)).norm(), 1e-12);
  // A pure turn: the point of time 1 is turned by half the frame's rotation.
  motion = Eigen::Isometry3d(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()));
  const Points turned = deskewScan({{10, 0, 0}}, {1.0}, motion);
  EXPECT_LT((turned[0] - Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()) * pts[0]).norm(), 1e-12);
  const std::vector<double> az = azimuthTimes({{-1, 1e-9, 0}, {0, 1, 0}, {1, 0, 0}, {0, -1, 0}});
  EXPECT_NEAR(az[0], 0.0, 1e-6);
  EXPECT_NEAR(az[1], 0.25, 1e-12);
  EXPECT_NEAR(az[2], 0.5, 1e-12);
  EXPECT_NEAR(az[3], 0.75, 1e-12);
  EXPECT_THROW(deskewScan(pts, {0.0}, motion), std::invalid_argument);
}

// A corridor: two walls and a floor, nothing along x. Point-to-point matching cannot see motion
// along the axis; the solver must say so and keep the prediction there, while still fixing the
// constrained directions.
TEST(LidarOdometryParts, CorridorAxisIsHeldAtThePrediction) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(-60.0, 60.0), uw(-2.0, 2.0), uz(-1.5, 1.5);
  auto sample = [&](int i) {
    const double x = ux(rng);
    switch (i % 3) {
      case 0:
        return Eigen::Vector3d(x, -2.0, uz(rng));
      case 1:
        return Eigen::Vector3d(x, 2.0, uz(rng));
      default:
        return Eigen::Vector3d(x, uw(rng), -1.5);
    }
  };
  VoxelHashMap map(1.0, 20);
  for (int pass = 0; pass < 5; ++pass) {  // five sweeps over the corridor, as odometry adds them
    Points world;
    for (int i = 0; i < 30000; ++i) world.push_back(sample(i));
    map.add(voxelDownsample(world, 0.5));
  }
  // The sensor truly sits at x = 0.7, y = 0.1 with a 1 degree yaw; the guess has x = 0.4.
  Eigen::Isometry3d truth(Eigen::AngleAxisd(1.0 / kDeg, Eigen::Vector3d::UnitZ()));
  truth.translation() = Eigen::Vector3d(0.7, 0.1, 0.0);
  // The scan samples the same surfaces afresh (other points than the map's).
  Points scan;
  for (int i = 0; i < 30000; ++i) {
    const Eigen::Vector3d s = truth.inverse() * sample(i);
    if (s.norm() < 30.0) scan.push_back(s);
  }
  const Points source = voxelDownsample(scan, 1.5);
  Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
  guess.translation() = Eigen::Vector3d(0.4, 0.0, 0.0);
  PointToPointIcpParams p;
  p.threshold = 1.0;
  const PointToPointIcpResult held = alignPointToPoint(source, map, guess, p);
  EXPECT_GE(held.degenerate_directions, 1);
  // Along the axis: exactly where the guess put it. Across: the truth.
  EXPECT_NEAR(held.pose.translation().x(), 0.4, 0.01);
  EXPECT_NEAR(held.pose.translation().y(), 0.1, 0.03);
  EXPECT_NEAR(held.pose.translation().z(), 0.0, 0.03);
  EXPECT_LT(std::abs(Eigen::AngleAxisd(held.pose.linear()).angle() - 1.0 / kDeg), 0.1 / kDeg);
  // Without the hold the pairs slide: the axis is not where the guess put it.
  p.degeneracy_ratio = 0.0;
  const PointToPointIcpResult free = alignPointToPoint(source, map, guess, p);
  EXPECT_EQ(free.degenerate_directions, 0);
  std::printf("corridor: held x %.4f (ratio %.2e), free x %.4f\n", held.pose.translation().x(),
              held.eigen_ratio, free.pose.translation().x());
}

TEST(LidarOdometry, ConsecutiveMotionsAgreeWithPairwiseGicp) {
  const std::vector<Eigen::Isometry3d> poses = runOdometry({0, 1, 2, 3, 4, 5});
  ASSERT_EQ(poses.size(), 6u);
  for (std::size_t k = 1; k <= 5; ++k) {
    const Eigen::Isometry3d odo = relative(poses[k - 1], poses[k]);
    const Eigen::Isometry3d oracle = gicpMotion(kittiScans()[k - 1], kittiScans()[k]);
    const PoseError e = poseError(odo, oracle);
    EXPECT_LT(e.translation, 0.03) << "frames " << k - 1 << "->" << k;
    EXPECT_LT(e.rotation_deg, 0.2) << "frames " << k - 1 << "->" << k;
    // The car moves 0.67-0.74 m per frame on these scans (docs/KITTI.md).
    EXPECT_GT(odo.translation().norm(), 0.6);
    EXPECT_LT(odo.translation().norm(), 0.8);
    std::printf("frames %zu->%zu: odometry %.4f m, gicp %.4f m, difference %.4f m %.4f deg\n",
                k - 1, k, odo.translation().norm(), oracle.translation().norm(), e.translation,
                e.rotation_deg);
  }
}

TEST(LidarOdometry, ReversedOrderGivesTheInverseMotions) {
  const std::vector<Eigen::Isometry3d> fwd = runOdometry({0, 1, 2, 3, 4, 5});
  const std::vector<Eigen::Isometry3d> rev = runOdometry({5, 4, 3, 2, 1, 0});
  for (std::size_t k = 1; k <= 5; ++k) {
    const Eigen::Isometry3d forward = relative(fwd[k - 1], fwd[k]);  // k-1 -> k
    // rev[i] is frame 5 - i: the step from frame k to frame k-1 is rev[5-k] -> rev[6-k].
    const Eigen::Isometry3d backward = relative(rev[5 - k], rev[6 - k]);
    const PoseError e = poseError(forward.inverse(), backward);
    EXPECT_LT(e.translation, 0.03) << "frames " << k - 1 << "<->" << k;
    EXPECT_LT(e.rotation_deg, 0.2) << "frames " << k - 1 << "<->" << k;
  }
}

TEST(LidarOdometry, RecoversKnownMotionsOfARealScan) {
  const Points& scan = kittiScans()[0];
  Eigen::Isometry3d general(
      Eigen::AngleAxisd(5.0 / kDeg, Eigen::Vector3d(0.2, -0.3, 1.0).normalized()));
  general.translation() = Eigen::Vector3d(0.6, -0.8, 0.0);  // 1 m
  const Eigen::Isometry3d turn(Eigen::AngleAxisd(10.0 / kDeg, Eigen::Vector3d::UnitZ()));
  for (const Eigen::Isometry3d& motion : {general, turn}) {
    LidarOdometry odo;
    odo.registerFrame(scan);
    // The sensor moved by `motion`: it sees the same world points at motion^-1 * p.
    const OdometryResult r = odo.registerFrame(transformed(scan, motion.inverse()));
    const PoseError e = poseError(r.pose, motion);
    EXPECT_LT(e.translation, 0.02);
    EXPECT_LT(e.rotation_deg, 0.1);
    EXPECT_EQ(r.degenerate_directions, 0);
    std::printf("known motion: error %.4f m %.4f deg, %d iterations\n", e.translation,
                e.rotation_deg, r.iterations);
  }
}

TEST(LidarOdometry, ScanThinnedToATenthStillRegisters) {
  std::mt19937 rng(7);
  Points thin;
  for (const auto& p : kittiScans()[1]) {
    if (std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 0.1) thin.push_back(p);
  }
  LidarOdometry odo;
  odo.registerFrame(kittiScans()[0]);
  const OdometryResult r = odo.registerFrame(thin);
  const Eigen::Isometry3d oracle = gicpMotion(kittiScans()[0], kittiScans()[1]);
  const PoseError e = poseError(r.pose, oracle);
  EXPECT_LT(e.translation, 0.05);
  EXPECT_LT(e.rotation_deg, 0.3);
  EXPECT_LT(thin.size(), kittiScans()[1].size() / 9);
}

TEST(LidarOdometry, EmptyOrNanScanIsAnErrorNamingTheFrame) {
  LidarOdometry odo;
  odo.registerFrame(kittiScans()[0]);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto message = [&](const Points& pts, const std::string& name) {
    try {
      odo.registerFrame(pts, {}, name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({}, "").find("frame 1"), std::string::npos) << message({}, "");
  EXPECT_NE(message({{nan, 0, 0}, {0, nan, 1}}, "").find("frame 1"), std::string::npos);
  EXPECT_NE(message({{nan, nan, nan}}, "000042.bin").find("000042.bin"), std::string::npos);
  EXPECT_NE(message({{0.5, 0, 0}}, "near").find("no point between"), std::string::npos);
  // a few dozen points constrain no pose: refused naming the frame
  const Points few(kittiScans()[1].begin(), kittiScans()[1].begin() + 30);
  const std::string m = message(few, "000001.bin");
  EXPECT_EQ(m.rfind("000001.bin: ", 0), 0u) << m;
  EXPECT_NE(m.find("at least 100 needed"), std::string::npos) << m;
  EXPECT_EQ(odo.poses().size(), 1u);  // nothing was added by the bad scans
  const OdometryResult r = odo.registerFrame(kittiScans()[1]);
  EXPECT_GT(r.pose.translation().norm(), 0.6);
  LidarOdometryConfig bad;
  bad.voxel_size = 0.0;
  EXPECT_THROW(LidarOdometry{bad}, std::invalid_argument);
  bad = {};
  bad.deskew = true;
  LidarOdometry needs_times(bad);
  EXPECT_THROW(needs_times.registerFrame(kittiScans()[0]), std::invalid_argument);
}

TEST(LidarOdometry, RealScansAreNotDegenerateAndDeskewStaysClose) {
  LidarOdometry plain;
  LidarOdometryConfig cfg;
  cfg.deskew = true;
  LidarOdometry deskewed(cfg);
  for (std::size_t f = 0; f <= 5; ++f) {
    const OdometryResult a = plain.registerFrame(kittiScans()[f]);
    const OdometryResult b = deskewed.registerFrame(kittiScans()[f], azimuthTimes(kittiScans()[f]));
    EXPECT_EQ(a.degenerate_directions, 0) << "frame " << f;
    EXPECT_FALSE(a.restarted) << "frame " << f;
    // KITTI's scans are motion-compensated already; deskew may only move the poses a little.
    EXPECT_LT(poseError(a.pose, b.pose).translation, 0.1 * static_cast<double>(f) + 1e-9);
  }
}

}  // namespace metricmap
