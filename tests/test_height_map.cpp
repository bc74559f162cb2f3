// HeightMap: every valid pixel accounted for, counts equal a brute-force recount, a synthetic
// box on a floor gives obstacles exactly on its footprint, --auto-floor finds the carpet.
#include <cmath>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/depth_image.h"
#include "metricmap/mapping/floor_fit.h"
#include "metricmap/mapping/height_map.h"
#include "test_data.h"

namespace metricmap {
namespace {

const std::string kKinect = "pcl_grabber_kinect_depth/";
const std::string kFrame = "20121214T142255.814212";

pcl::PointCloud<pcl::PointXYZ> kinectCloud() {
  const DepthImage depth =
      readDepthImage(dataPath(kKinect + "tiff/frame_" + kFrame + "_depth.tiff"));
  const CameraIntrinsics k = readPclGrabberXml(dataPath(kKinect + "xml/frame_" + kFrame + ".xml"));
  return depthToCloud(depth, k, 0.001);
}

// Depth image (mm) of a floor z = 0 and a box, seen from `height` with `pitch` down.
DepthImage renderBoxScene(const CameraIntrinsics& k, double height, double pitch,
                          const Eigen::Vector3d& box_lo, const Eigen::Vector3d& box_hi) {
  const Eigen::Isometry3d pose = cameraToMap(height, pitch, 0.0);
  DepthImage img;
  img.width = 640;
  img.height = 480;
  img.kind = "tiff";
  img.values.assign(640 * 480, 0);
  for (int v = 0; v < 480; ++v) {
    for (int u = 0; u < 640; ++u) {
      const Eigen::Vector3d d_opt((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);  // z_opt = t
      const Eigen::Vector3d o = pose.translation(), d = pose.linear() * d_opt;
      double best = INFINITY;
      if (d.z() < 0) best = -o.z() / d.z();
      double t0 = 0, t1 = INFINITY;  // slab test
      bool hit = true;
      for (int a = 0; a < 3 && hit; ++a) {
        if (std::fabs(d[a]) < 1e-12) {
          hit = o[a] >= box_lo[a] && o[a] <= box_hi[a];
          continue;
        }
        double ta = (box_lo[a] - o[a]) / d[a], tb = (box_hi[a] - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        hit = t0 <= t1;
      }
      if (hit && t0 > 0) best = std::min(best, t0);
      if (std::isfinite(best) && best < 60.0) {
        img.values[static_cast<std::size_t>(v) * 640 + u] =
            static_cast<std::uint16_t>(std::lround(best * 1000));
      }
    }
  }
  return img;
}

}  // namespace

TEST(HeightMap, AccountsForEveryValidPixelAndMatchesARecount) {
  const auto cloud = kinectCloud();
  const FloorPlane floor = fitFloor(cloud, 0.02);
  const Eigen::Isometry3d pose = cameraToMapFromFloor(floor.normal, floor.d);
  HeightMapParams p;
  p.resolution = 0.02;
  p.map_size = 100;  // 2 m: some points fall outside
  p.z_bins = {0.03, 0.3};
  HeightMap map(p);
  map.addFrame(cloud, pose);
  map.addFrame(cloud, pose);  // a second frame adds, it does not overwrite
  const HeightMapStatistics& s = map.statistics();
  std::uint64_t inside = 0;
  for (auto b : s.bin_counts) inside += b;
  std::size_t valid = 0;
  for (const auto& q : cloud) valid += std::isfinite(q.z) ? 1 : 0;
  EXPECT_EQ(s.valid_points, 2 * valid);
  EXPECT_EQ(inside + s.points_outside_map, s.valid_points);
  EXPECT_GT(s.points_outside_map, 0u);

  // Brute force: transform in double, std::floor, linear scan over the edges.
  std::map<std::tuple<long, long, long>, std::uint32_t> ref;
  for (const auto& q : cloud) {
    if (!std::isfinite(q.z)) continue;
    const Eigen::Vector3d m = pose * q.getVector3fMap().cast<double>();
    const long col = static_cast<long>(std::floor(m.x() / 0.02)) + 50;
    const long row = 50 - 1 - static_cast<long>(std::floor(m.y() / 0.02));
    long bin = 0;
    while (bin < 2 && m.z() >= p.z_bins[static_cast<std::size_t>(bin)]) ++bin;
    if (col >= 0 && col < 100 && row >= 0 && row < 100) ref[{row, col, bin}] += 2;
  }
  std::size_t mismatches = 0, nonzero = 0;
  for (std::size_t r = 0; r < 100; ++r) {
    for (std::size_t c = 0; c < 100; ++c) {
      for (std::size_t b = 0; b < 3; ++b) {
        const auto it =
            ref.find({static_cast<long>(r), static_cast<long>(c), static_cast<long>(b)});
        const std::uint32_t expected = it == ref.end() ? 0 : it->second;
        nonzero += expected > 0;
        mismatches += map.count(r, c, b) != expected;
      }
    }
  }
  // The map transforms in float; a point within float rounding of a cell edge may differ.
  EXPECT_LE(mismatches, nonzero / 1000 + 2);
  EXPECT_GT(nonzero, 1000u);
}

TEST(HeightMap, AutoFloorFindsTheCarpet) {
  const auto cloud = kinectCloud();
  const FloorPlane floor = fitFloor(cloud, 0.02);
  EXPECT_GT(floor.inliers, 20000u);
  EXPECT_GT(floor.cameraHeight(), 0.3);
  EXPECT_LT(floor.cameraHeight(), 1.5);
  HeightMapParams p;
  p.resolution = 0.01;
  p.map_size = 400;
  p.z_bins = {0.03, 0.5};
  HeightMap map(p);
  map.addFrame(cloud, cameraToMapFromFloor(floor.normal, floor.d));
  const auto& bins = map.statistics().bin_counts;
  EXPECT_GT(bins[0], bins[1]);  // the lowest bin (the carpet) holds the most points
  EXPECT_GT(bins[0], bins[2]);
  EXPECT_GT(map.obstacleCells(), 100u);  // the laptop and the box
}

TEST(HeightMap, BoxOnAFloorGivesObstaclesExactlyOnItsFootprint) {
  const CameraIntrinsics k = parseIntrinsics("525,525,320,240");
  const Eigen::Vector3d lo(-0.18, 1.52, 0.0), hi(0.18, 1.88, 0.3);
  const DepthImage img = renderBoxScene(k, 1.0, 30 * M_PI / 180, lo, hi);
  HeightMapParams p;
  p.resolution = 0.05;
  p.map_size = 100;
  p.z_bins = {0.05, 0.5};
  HeightMap map(p);
  map.addFrame(depthToCloud(img, k, 0.001), cameraToMap(1.0, 30 * M_PI / 180, 0.0));
  std::set<std::pair<std::size_t, std::size_t>> expected;
  for (int c = -4; c < 4; ++c) {        // x in [-0.2, 0.2)
    for (int yc = 30; yc < 38; ++yc) {  // y in [1.5, 1.9)
      expected.insert({static_cast<std::size_t>(50 - 1 - yc), static_cast<std::size_t>(50 + c)});
    }
  }
  std::set<std::pair<std::size_t, std::size_t>> actual;
  for (std::size_t r = 0; r < 100; ++r) {
    for (std::size_t c = 0; c < 100; ++c) {
      if (map.obstacle(r, c)) actual.insert({r, c});
    }
  }
  EXPECT_EQ(actual, expected);
  EXPECT_GT(map.exploredCells(), expected.size());
}

TEST(HeightMap, DigitizeEdgesAndBadParameters) {
  HeightMapParams p;
  p.resolution = 1.0;
  p.map_size = 4;
  p.z_bins = {0.0, 1.0};
  HeightMap map(p);
  pcl::PointCloud<pcl::PointXYZ> pts;
  pts.push_back(pcl::PointXYZ(0.5f, 0.5f, -0.1f));  // below the first edge: bin 0
  pts.push_back(pcl::PointXYZ(0.5f, 0.5f, 0.0f));   // on an edge: the bin above (np.digitize)
  pts.push_back(pcl::PointXYZ(0.5f, 0.5f, 1.0f));   // on the last edge: the top bin
  pts.push_back(pcl::PointXYZ(9.0f, 0.5f, 0.5f));   // outside
  map.addFrame(pts, Eigen::Isometry3d::Identity());
  EXPECT_EQ(map.count(1, 2, 0), 1u);  // x 0.5 -> col 2, y 0.5 -> row 1
  EXPECT_EQ(map.count(1, 2, 1), 1u);
  EXPECT_EQ(map.count(1, 2, 2), 1u);
  EXPECT_EQ(map.statistics().points_outside_map, 1u);

  HeightMapParams bad = p;
  bad.map_size = 0;
  EXPECT_THROW(HeightMap{bad}, std::invalid_argument);
  bad = p;
  bad.z_bins = {1.0, 0.5};
  EXPECT_THROW(HeightMap{bad}, std::invalid_argument);
  bad.z_bins = {0.5};  // no middle (obstacle) bin between a floor and a ceiling edge
  EXPECT_THROW(HeightMap{bad}, std::invalid_argument);
  bad.z_bins = {};
  EXPECT_THROW(HeightMap{bad}, std::invalid_argument);
  bad = p;
  bad.resolution = 0.0;
  EXPECT_THROW(HeightMap{bad}, std::invalid_argument);
  bad = p;
  bad.map_size = 100000;  // 1e10 cells x 3 bins x 4 bytes
  try {
    HeightMap huge(bad);
    ADD_FAILURE() << "no error for a 100000 x 100000 map";
  } catch (const CapacityError& e) {
    EXPECT_NE(std::string(e.what()).find("MiB"), std::string::npos) << e.what();
  }
}

TEST(HeightMap, FloorFitRefusesStrideZeroAndBadThresholds) {
  const auto cloud = kinectCloud();
  EXPECT_THROW(fitFloor(cloud, 0.02, 0), std::invalid_argument);  // was a division by zero
  EXPECT_THROW(fitFloor(cloud, 0.0), std::invalid_argument);
  EXPECT_THROW(fitFloor(cloud, std::nan("")), std::invalid_argument);
  EXPECT_GT(fitFloor(cloud, 0.02, 1).inliers, fitFloor(cloud, 0.02, 8).inliers);
}

}  // namespace metricmap
