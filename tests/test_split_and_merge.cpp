// SplitAndMerge on synthetic rooms (ray-cast with noise), merge/purge rules, and a property test.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "metricmap/io/laser_scan.h"
#include "metricmap/lines/split_and_merge.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Polygon = std::vector<Eigen::Vector2d>;

// Range from `origin` along `angle` to the nearest edge of a closed polygon.
double castRay(const Polygon& poly, const Eigen::Vector2d& origin, double angle) {
  const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d a = poly[i], b = poly[(i + 1) % poly.size()];
    const Eigen::Vector2d e = b - a;
    const double den = d.x() * e.y() - d.y() * e.x();
    if (std::fabs(den) < 1e-12) continue;
    const Eigen::Vector2d w = a - origin;
    const double t = (w.x() * e.y() - w.y() * e.x()) / den;
    const double s = (w.x() * d.y() - w.y() * d.x()) / den;
    if (t > 0 && s >= 0 && s <= 1) best = std::min(best, t);
  }
  return best;
}

Cloud::Ptr scanPolygon(const Polygon& poly, const Eigen::Vector2d& origin, double start,
                       double step_deg, int beams, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  auto cloud = std::make_shared<Cloud>();
  for (int k = 0; k < beams; ++k) {
    const double a = start + k * step_deg * M_PI / 180.0;
    const double r = castRay(poly, origin, a) + noise(rng);
    cloud->push_back(pcl::PointXYZ(static_cast<float>(origin.x() + r * std::cos(a)),
                                   static_cast<float>(origin.y() + r * std::sin(a)), 0.0f));
  }
  return cloud;
}

std::vector<LineSegment> run(const Cloud::Ptr& cloud, const SplitAndMergeParams& p,
                             std::vector<pcl::PointIndices>* members = nullptr) {
  SplitAndMerge<pcl::PointXYZ> sam;
  sam.setParams(p);
  sam.setInputCloud(cloud);
  std::vector<LineSegment> segs;
  std::vector<pcl::PointIndices> m;
  sam.segment(segs, m);
  if (members) *members = m;
  return segs;
}

// Every corner has a segment endpoint within `tol`, and every endpoint is near a corner.
void expectCorners(const std::vector<LineSegment>& segs, const Polygon& corners, double tol) {
  for (const Eigen::Vector2d& c : corners) {
    double best = 1e9;
    for (const LineSegment& s : segs)
      best = std::min({best, (s.start - c).norm(), (s.end - c).norm()});
    EXPECT_LT(best, tol) << "corner " << c.transpose();
  }
  for (const LineSegment& s : segs) {
    for (const Eigen::Vector2d& e : {s.start, s.end}) {
      double best = 1e9;
      for (const Eigen::Vector2d& c : corners) best = std::min(best, (e - c).norm());
      EXPECT_LT(best, tol) << "endpoint " << e.transpose();
    }
  }
}

std::string describe(const std::vector<LineSegment>& segs) {
  std::ostringstream os;
  for (const LineSegment& s : segs) {
    os << "[" << s.first_index << "-" << s.last_index << " n=" << s.points << " (" << s.start.x()
       << "," << s.start.y() << ")->(" << s.end.x() << "," << s.end.y() << ")] ";
  }
  return os.str();
}

SplitAndMergeParams roomParams() {
  SplitAndMergeParams p;
  p.distance_threshold = 0.02;
  p.angle_threshold = 5 * M_PI / 180;
  p.min_points = 5;
  p.min_length = 0.05;
  return p;
}

}  // namespace

TEST(SplitAndMerge, RectangleRoomGivesItsFourWalls) {
  const Polygon room = {{-2, -1}, {2, -1}, {2, 2}, {-2, 2}};
  const double start = std::atan2(-1.0, -2.0) + 1e-4;  // start just past a corner
  auto cloud = scanPolygon(room, {0, 0}, start, 0.05, 7200, 0.001, 1);
  const auto segs = run(cloud, roomParams());
  ASSERT_EQ(segs.size(), 4u) << describe(segs);
  expectCorners(segs, room, 0.01);
  for (std::size_t k = 0; k + 1 < segs.size(); ++k) {
    EXPECT_NEAR(std::fabs(segs[k].angleTo(segs[k + 1])), M_PI / 2, 0.02);
  }
}

TEST(SplitAndMerge, LShapedCorridorGivesItsSixWalls) {
  const Polygon corridor = {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
  const Eigen::Vector2d origin(0.5, 0.5);
  const double start = std::atan2(-0.5, -0.5) + 1e-4;
  // Fine steps: the far ends of the arms are seen at 82 degrees of incidence.
  auto cloud = scanPolygon(corridor, origin, start, 0.0125, 28800, 0.001, 2);
  const auto segs = run(cloud, roomParams());
  ASSERT_EQ(segs.size(), 6u) << describe(segs);
  expectCorners(segs, corridor, 0.01);
  if (HasFailure()) ADD_FAILURE() << describe(segs);
}

TEST(SplitAndMerge, MergeJoinsCollinearPiecesButNotACorner) {
  // A wall with a 1 degree kink in the middle: split cuts it there, merge rejoins it.
  auto wall = std::make_shared<Cloud>();
  const double kink = std::tan(1.0 * M_PI / 180);
  for (int i = 0; i <= 200; ++i) {
    const double x = -2.0 + 0.02 * i;
    wall->push_back(
        pcl::PointXYZ(static_cast<float>(x), static_cast<float>(1.5 + (x > 0 ? x * kink : 0)), 0));
  }
  SplitAndMergeParams p;
  p.distance_threshold = 0.01;
  p.angle_threshold = 0.0;
  EXPECT_EQ(run(wall, p).size(), 2u);
  p.angle_threshold = 0.5 * M_PI / 180;  // tighter than the kink: stays apart
  EXPECT_EQ(run(wall, p).size(), 2u);
  p.angle_threshold = 5 * M_PI / 180;
  const auto merged = run(wall, p);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].points, 201u);
  EXPECT_EQ(merged[0].first_index, 0);
  EXPECT_EQ(merged[0].last_index, 200);

  auto corner = std::make_shared<Cloud>();
  for (int i = 0; i <= 100; ++i) corner->push_back(pcl::PointXYZ(0.02f * i, 1.0f, 0));
  for (int i = 1; i <= 100; ++i) corner->push_back(pcl::PointXYZ(2.0f, 1.0f + 0.02f * i, 0));
  p.distance_threshold = 0.01;
  p.angle_threshold = 20 * M_PI / 180;
  EXPECT_EQ(run(corner, p).size(), 2u);
}

TEST(SplitAndMerge, PurgeBeforeMergeJoinsAWallBrokenByChairLegs) {
  auto cloud = std::make_shared<Cloud>();
  for (int i = 0; i <= 100; ++i) cloud->push_back(pcl::PointXYZ(-2.0f + 0.02f * i, 2.0f, 0));
  for (int i = 0; i < 3; ++i) cloud->push_back(pcl::PointXYZ(0.05f + 0.01f * i, 1.0f, 0));  // leg
  for (int i = 0; i <= 100; ++i) cloud->push_back(pcl::PointXYZ(0.2f + 0.02f * i, 2.0f, 0));
  SplitAndMergeParams p;
  p.distance_threshold = 0.02;
  p.angle_threshold = 5 * M_PI / 180;
  p.min_points = 5;
  p.purge_order = PurgeOrder::BeforeMerge;
  std::vector<pcl::PointIndices> members;
  const auto joined = run(cloud, p, &members);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(joined[0].first_index, 0);
  EXPECT_EQ(joined[0].last_index, 204);
  EXPECT_GE(joined[0].points, 201u);  // the wall (a wall point may go with the leg's piece)
  EXPECT_LE(joined[0].points, 202u);  // but not the leg's 3 points
  for (int leg = 101; leg <= 103; ++leg) {
    EXPECT_EQ(std::count(members[0].indices.begin(), members[0].indices.end(), leg), 0);
  }
  p.purge_order = PurgeOrder::AfterMerge;
  EXPECT_EQ(run(cloud, p).size(), 2u);
}

TEST(SplitAndMerge, PurgeRules) {
  auto cloud = std::make_shared<Cloud>();
  for (int i = 0; i < 50; ++i) cloud->push_back(pcl::PointXYZ(0.02f * i, 1.0f, 0));       // 0.98 m
  for (int i = 0; i < 4; ++i) cloud->push_back(pcl::PointXYZ(1.5f, 1.5f + 0.1f * i, 0));  // 4 pts
  SplitAndMergeParams p;
  p.distance_threshold = 0.05;
  p.angle_threshold = 0.0;
  p.min_points = 0;  // no purge
  p.min_length = 0.0;
  EXPECT_EQ(run(cloud, p).size(), 2u);  // the wall and the post
  p.min_points = 5;
  EXPECT_EQ(run(cloud, p).size(), 1u);
  p.min_points = 0;
  p.min_length = 0.5;
  const auto long_only = run(cloud, p);
  ASSERT_EQ(long_only.size(), 1u);
  EXPECT_EQ(long_only[0].points, 50u);
}

TEST(SplitAndMerge, NoPointLostAndAllWithinThreshold) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    auto cloud = std::make_shared<Cloud>();
    Eigen::Vector2d p(0, 0), dir(1, 0);
    for (int i = 0; i < 400; ++i) {
      if (i % 40 == 0) dir = Eigen::Vector2d(u(rng), u(rng)).normalized();
      p += 0.02 * dir + 0.005 * Eigen::Vector2d(u(rng), u(rng));
      const bool invalid = (i % 37) == 5;
      const float nan = std::numeric_limits<float>::quiet_NaN();
      cloud->push_back(
          invalid ? pcl::PointXYZ(nan, nan, nan)
                  : pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()), 0));
    }
    SplitAndMergeParams prm;
    prm.distance_threshold = 0.01 + 0.002 * trial;
    prm.angle_threshold = 0.0;
    prm.min_points = 0;  // no purge: every valid point belongs to a segment
    prm.min_length = 0.0;
    std::vector<pcl::PointIndices> members;
    const auto segs = run(cloud, prm, &members);
    std::vector<int> seen(cloud->size(), 0);
    for (std::size_t k = 0; k < segs.size(); ++k) {
      EXPECT_EQ(members[k].indices.size(), segs[k].points);
      EXPECT_EQ(members[k].indices.front(), segs[k].first_index);
      EXPECT_EQ(members[k].indices.back(), segs[k].last_index);
      for (int i : members[k].indices) {
        ++seen[static_cast<std::size_t>(i)];
        const Eigen::Vector2d q((*cloud)[i].x, (*cloud)[i].y);
        EXPECT_LE(segs[k].distance(q), prm.distance_threshold + 1e-9) << "trial " << trial;
      }
    }
    for (std::size_t i = 0; i < cloud->size(); ++i) {
      EXPECT_EQ(seen[i], std::isfinite((*cloud)[i].x) ? 1 : 0)
          << "beam " << i << " trial " << trial;
    }
  }
}

TEST(SplitAndMerge, MaxGapSplitsAndChi2Works) {
  auto cloud = std::make_shared<Cloud>();
  for (int i = 0; i < 20; ++i) cloud->push_back(pcl::PointXYZ(0.05f * i, 2.0f, 0));
  for (int i = 0; i < 20; ++i) cloud->push_back(pcl::PointXYZ(2.0f + 0.05f * i, 2.0f, 0));
  SplitAndMergeParams p;
  p.angle_threshold = 0.0;
  EXPECT_EQ(run(cloud, p).size(), 1u);  // collinear: one chord across the gap
  p.max_gap = 0.5;
  EXPECT_EQ(run(cloud, p).size(), 2u);
  p.max_gap = 0.0;
  p.chi2_split = true;
  p.range_sigma = 0.01;
  EXPECT_EQ(run(cloud, p).size(), 1u);  // exact line: no point is off it
}

TEST(SplitAndMerge, DegenerateInputsAndBadParameters) {
  auto empty = std::make_shared<Cloud>();
  EXPECT_TRUE(run(empty, SplitAndMergeParams()).empty());
  auto one = std::make_shared<Cloud>();
  one->push_back(pcl::PointXYZ(1, 1, 0));
  SplitAndMergeParams keep_all;
  keep_all.min_points = 0;
  keep_all.min_length = 0.0;
  const auto s = run(one, keep_all);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].points, 1u);
  SplitAndMerge<pcl::PointXYZ> sam;
  EXPECT_THROW(sam.setDistanceThreshold(0.0), std::invalid_argument);
  EXPECT_THROW(sam.setDistanceThreshold(std::nan("")), std::invalid_argument);
  EXPECT_THROW(sam.setAngleThreshold(-0.1), std::invalid_argument);
  EXPECT_THROW(sam.setMinLength(-1.0), std::invalid_argument);
  EXPECT_THROW(sam.setMaxGap(INFINITY), std::invalid_argument);
}

TEST(SplitAndMerge, MergeReachesAFixpointOnARealLog) {
  // Every scan of the URG-04LX log: after the merge no two neighbouring segments' chords differ
  // by less than the angle threshold (a merged segment is compared again with the one before).
  const ScanLog log = readScanLines(
      std::string(METRICMAP_DATA_DIR) + "/breezyslam_mines_urg04lx/exp2.dat", urg04lxMinesFormat());
  const SplitAndMergeParams defaults;
  for (double angle_deg : {5.0, 10.0, 20.0}) {
    SplitAndMergeParams p = defaults;
    p.angle_threshold = angle_deg * M_PI / 180.0;
    std::size_t checked = 0;
    for (std::size_t k = 0; k < log.scans.size(); k += 5) {
      const auto cloud = std::make_shared<Cloud>(scanToCloud(log.scans[k]));
      const auto segs = run(cloud, p);
      for (std::size_t i = 1; i < segs.size(); ++i) {
        ASSERT_GE(std::fabs(segs[i - 1].angleTo(segs[i])), p.angle_threshold)
            << "scan " << k << " segments " << i - 1 << "," << i << " at " << angle_deg << " deg";
        ++checked;
      }
    }
    EXPECT_GT(checked, 1000u);
  }
}

}  // namespace metricmap
