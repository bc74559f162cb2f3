// Builds with 1, 2, 3 and 5 threads (oversubscribed on this machine) give the same cells,
// nodes, counts and means, bit for bit, on real KITTI points (with NaN points and an index
// subset as well); the VoxelGrid-equivalent grid keeps its cell count; the odometry's poses are
// the same bits for every thread count.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/detail/thread_team.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/occupancy/log_odds_map.h"
#include "metricmap/occupancy/octomap_io.h"
#include "metricmap/octree/adaptive_octree.h"
#include "metricmap/registration/lidar_odometry.h"
#include "temp_dir.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/// Frames 0-5 of the bundled KITTI sequence (746 k points: enough for five threads), with a
/// NaN point every 1000.
Cloud::ConstPtr kittiFrames() {
  static const Cloud::ConstPtr cloud = [] {
    auto c = std::make_shared<Cloud>();
    const KittiSequence seq{dataPath("kitti_odometry_00"), "00"};
    for (std::size_t i = 0; i < 6; ++i) {
      Cloud scan;
      loadCloud(seq.scan(i), scan);
      for (auto& p : scan) p.x += 40.0f * static_cast<float>(i);  // six scans side by side
      *c += scan;
    }
    for (std::size_t i = 0; i < c->size(); i += 1000) (*c)[i].y = std::nanf("");
    return c;
  }();
  return cloud;
}

bool sameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

void expectSameGrid(const OccupancyGrid<pcl::PointXYZ>& a, const OccupancyGrid<pcl::PointXYZ>& b,
                    unsigned threads) {
  ASSERT_EQ(a.getCells().size(), b.getCells().size()) << threads << " threads";
  EXPECT_EQ(a.getStatistics().total_cells, b.getStatistics().total_cells);
  EXPECT_EQ(a.getStatistics().skipped_points, b.getStatistics().skipped_points);
  for (std::size_t i = 0; i < a.getCells().size(); ++i) {
    const GridCell &x = a.getCells()[i], &y = b.getCells()[i];
    ASSERT_EQ(x.index, y.index) << "cell " << i << ", " << threads << " threads";
    ASSERT_EQ(x.count, y.count) << "cell " << i;
    ASSERT_EQ(x.first_point, y.first_point) << "cell " << i;
    ASSERT_TRUE(sameBits(x.mean, y.mean)) << "cell " << i << ", " << threads << " threads";
  }
}

TEST(Threads, GridCellsAndMeansDoNotDependOnTheThreadCount) {
  const auto cloud = kittiFrames();
  auto subset = std::make_shared<pcl::Indices>();
  for (int i = 0; i < static_cast<int>(cloud->size()); i += 3) subset->push_back(i);
  for (GridOrigin origin : {GridOrigin::WorldAligned, GridOrigin::CloudMinimum}) {
    for (bool with_indices : {false, true}) {
      OccupancyGrid<pcl::PointXYZ> one;
      one.setInputCloud(cloud);
      if (with_indices) one.setIndices(subset);
      one.setCellSize(0.1f);
      one.setOrigin(origin);
      one.setNumberOfThreads(1);
      one.compute();
      ASSERT_GT(one.getCells().size(), 100000u);
      for (unsigned threads : {2u, 3u, 5u}) {
        OccupancyGrid<pcl::PointXYZ> many;
        many.setInputCloud(cloud);
        if (with_indices) many.setIndices(subset);
        many.setCellSize(0.1f);
        many.setOrigin(origin);
        many.setNumberOfThreads(threads);
        many.compute();
        expectSameGrid(one, many, threads);
      }
    }
  }
}

// Occupancy: the beams of a scan cast on 1, 2, 3 and 5 threads give the same voxels, log-odds,
// visiting order, report and .bt bytes (OctoMap's model at 0.2 m / 50 m; two scans, so that the
// second updates voxels the first made).
TEST(Threads, LogOddsMapDoesNotDependOnTheThreadCount) {
  const auto cloud = kittiFrames();
  Cloud second = *cloud;
  for (auto& p : second) p.y += 0.5f;
  auto build = [&](unsigned threads, std::vector<ScanInsertReport>& reports) {
    LogOddsParams params;
    params.resolution = 0.2;
    params.max_range = 50.0;
    LogOddsMap map(params);
    map.setThreads(threads);
    reports.push_back(map.insertScan(*cloud, Eigen::Vector3f(100.0f, 0.0f, 0.0f)));
    reports.push_back(map.insertScan(second, Eigen::Vector3f(60.0f, 1.0f, 0.5f)));
    return map;
  };
  auto bytes = [](const LogOddsMap& map, const std::string& dir, unsigned threads) {
    const std::string path = dir + "/t" + std::to_string(threads) + ".bt";
    writeOctomap(map, path);
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  TempDir dir("threads_bt");
  std::vector<ScanInsertReport> one_reports;
  const LogOddsMap one = build(1, one_reports);
  std::vector<std::pair<VoxelKey, float>> one_voxels;
  one.forEachKnown([&](const VoxelKey& k, float l) { one_voxels.emplace_back(k, l); });
  ASSERT_GT(one_voxels.size(), 500000u);
  ASSERT_GT(one_reports[0].beams_cut, 1000u);
  const std::string one_bt = bytes(one, dir.path.string(), 1);
  for (unsigned threads : {2u, 3u, 5u}) {
    std::vector<ScanInsertReport> reports;
    const LogOddsMap many = build(threads, reports);
    for (std::size_t s = 0; s < 2; ++s) {
      EXPECT_EQ(reports[s].non_finite, one_reports[s].non_finite) << threads;
      EXPECT_EQ(reports[s].beams, one_reports[s].beams) << threads;
      EXPECT_EQ(reports[s].beams_cut, one_reports[s].beams_cut) << threads;
      EXPECT_EQ(reports[s].hit_voxels, one_reports[s].hit_voxels) << threads;
      EXPECT_EQ(reports[s].miss_voxels, one_reports[s].miss_voxels) << threads;
    }
    std::size_t k = 0;
    bool same = many.knownVoxels() == one.knownVoxels();
    many.forEachKnown([&](const VoxelKey& key, float l) {
      if (k >= one_voxels.size() || !(key == one_voxels[k].first) ||
          std::memcmp(&l, &one_voxels[k].second, sizeof l) != 0)
        same = false;
      ++k;
    });
    EXPECT_TRUE(same && k == one_voxels.size()) << threads << " threads";
    EXPECT_TRUE(bytes(many, dir.path.string(), threads) == one_bt) << threads << " threads";
  }
}

TEST(Threads, OctreeNodesAndMeansDoNotDependOnTheThreadCount) {
  const auto cloud = kittiFrames();
  for (bool cubic : {false, true}) {
    AdaptiveOctree<pcl::PointXYZ> one;
    one.setInputCloud(cloud);
    one.setMaxPointsPerLeaf(20);
    one.setMinCellSize(0.2f);
    one.setCubicRoot(cubic);
    one.setNumberOfThreads(1);
    one.compute();
    ASSERT_GT(one.getNodes().size(), 100000u);
    for (unsigned threads : {2u, 3u, 5u}) {
      AdaptiveOctree<pcl::PointXYZ> many;
      many.setInputCloud(cloud);
      many.setMaxPointsPerLeaf(20);
      many.setMinCellSize(0.2f);
      many.setCubicRoot(cubic);
      many.setNumberOfThreads(threads);
      many.compute();
      const auto &a = one.getNodes(), &b = many.getNodes();
      const std::vector<OctreeBox> box_a = one.getResult().allBounds(),
                                   box_b = many.getResult().allBounds();
      ASSERT_EQ(a.size(), b.size()) << threads << " threads";
      EXPECT_EQ(one.getStatistics().points, many.getStatistics().points);
      EXPECT_EQ(one.getStatistics().occupied_leaves, many.getStatistics().occupied_leaves);
      for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].count, b[i].count) << "node " << i;
        ASSERT_EQ(a[i].first_point, b[i].first_point) << "node " << i;
        ASSERT_EQ(a[i].depth, b[i].depth) << "node " << i;
        ASSERT_TRUE(sameBits(a[i].mean, b[i].mean)) << "node " << i << ", " << threads;
        ASSERT_TRUE(sameBits(box_a[i].min, box_b[i].min) && sameBits(box_a[i].max, box_b[i].max))
            << i;
      }
    }
  }
}

TEST(Threads, TeamRunsEveryThreadOncePerRunAndRethrows) {
  for (const unsigned size : {1u, 2u, 3u}) {
    ThreadTeam team(size);
    ASSERT_EQ(team.size(), size);
    std::vector<long> hits(size, 0);
    long total = 0;
    for (int run = 0; run < 2000; ++run) {
      team.run([&](unsigned t) { hits[t] += run; });
      total += run;
      // Now and then let the workers fall asleep between runs.
      if (run % 500 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    for (unsigned t = 0; t < size; ++t) EXPECT_EQ(hits[t], total) << "thread " << t;
    // The first failure by thread number is rethrown after all have finished; the team stays
    // usable.
    std::vector<int> finished(size, 0);
    try {
      team.run([&](unsigned t) {
        finished[t] = 1;
        if (t == size - 1) throw std::runtime_error("thread " + std::to_string(t));
      });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "thread " + std::to_string(size - 1));
    }
    EXPECT_EQ(std::count(finished.begin(), finished.end(), 1), static_cast<long>(size));
    int after = 0;
    std::mutex m;
    team.run([&](unsigned) {
      std::lock_guard<std::mutex> lock(m);
      ++after;
    });
    EXPECT_EQ(after, static_cast<int>(size));
  }
}

TEST(Threads, OdometryPosesDoNotDependOnTheThreadCount) {
  const KittiSequence seq{dataPath("kitti_odometry_00"), "00"};
  std::vector<Cloud> scans(6);
  for (std::size_t f = 0; f < scans.size(); ++f) loadCloud(seq.scan(f), scans[f]);
  auto run = [&](unsigned threads) {
    LidarOdometryConfig config;
    config.threads = threads;
    LidarOdometry odo(config);
    for (const Cloud& scan : scans) odo.registerFrame(scan);
    return odo.poses();
  };
  const std::vector<Eigen::Isometry3d> one = run(1);
  ASSERT_EQ(one.size(), scans.size());
  EXPECT_GT(one.back().translation().norm(), 3.0);  // the car moved: a real run, not identity
  for (unsigned threads : {2u, 3u, 5u}) {
    const std::vector<Eigen::Isometry3d> many = run(threads);
    ASSERT_EQ(many.size(), one.size());
    for (std::size_t f = 0; f < one.size(); ++f) {
      EXPECT_EQ(std::memcmp(one[f].matrix().data(), many[f].matrix().data(), sizeof(double) * 16),
                0)
          << "frame " << f << ", " << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace metricmap
