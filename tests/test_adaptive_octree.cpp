// AdaptiveOctree node for node against a plain recursive reference, plus invariants.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <pcl/common/common.h>

#include "metricmap/io/cloud_reader.h"
#include "metricmap/octree/adaptive_octree.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// The rule as the issue states it, written the obvious way: point lists, recursion, and
// mid = (lo + hi) / 2; a point goes up an axis iff p >= mid.
struct RefNode {
  Eigen::Vector3d lo, hi;
  unsigned depth = 0;
  std::vector<int> points;
  std::vector<RefNode> children;
};

void refBuild(RefNode& n, const Cloud& c, std::size_t max_points, double min_cell) {
  const double edge = (n.hi - n.lo).maxCoeff();
  if (!(n.points.size() > max_points && edge > min_cell && n.depth < kOctreeMaxDepth)) return;
  const Eigen::Vector3d mid = (n.lo + n.hi) / 2;
  n.children.resize(8);
  for (unsigned o = 0; o < 8; ++o) {
    RefNode& ch = n.children[o];
    ch.depth = n.depth + 1;
    for (int a = 0; a < 3; ++a) {
      const bool up = (o >> a) & 1u;
      ch.lo[a] = up ? mid[a] : n.lo[a];
      ch.hi[a] = up ? n.hi[a] : mid[a];
    }
  }
  for (int i : n.points) {
    const pcl::PointXYZ& p = c[i];
    const unsigned o =
        (p.x >= mid[0] ? 1u : 0u) | (p.y >= mid[1] ? 2u : 0u) | (p.z >= mid[2] ? 4u : 0u);
    n.children[o].points.push_back(i);
  }
  n.points.clear();
  for (RefNode& ch : n.children) refBuild(ch, c, max_points, min_cell);
}

std::uint64_t refCount(const RefNode& n) {
  if (n.children.empty()) return n.points.size();
  std::uint64_t s = 0;
  for (const RefNode& ch : n.children) s += refCount(ch);
  return s;
}

Eigen::Vector3d refSum(const RefNode& n, const Cloud& c) {
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  if (n.children.empty()) {
    for (int i : n.points) s += Eigen::Vector3d(c[i].x, c[i].y, c[i].z);
    return s;
  }
  for (const RefNode& ch : n.children) s += refSum(ch, c);
  return s;
}

void compareNodes(const RefNode& ref, const OctreeResult& tree, std::size_t id, const Cloud& c,
                  std::size_t& visited) {
  ++visited;
  const OctreeNode& n = tree.nodes[id];
  ASSERT_EQ(n.depth, ref.depth);
  const OctreeBox box = tree.bounds(id);
  ASSERT_EQ(box.min, ref.lo) << "node " << id;
  ASSERT_EQ(box.max, ref.hi) << "node " << id;
  ASSERT_EQ(n.isLeaf(), ref.children.empty()) << "node " << id << " depth " << n.depth;
  const std::uint64_t count = refCount(ref);
  ASSERT_EQ(n.count, count) << "node " << id;
  if (count > 0) {
    const Eigen::Vector3d mean = refSum(ref, c) / static_cast<double>(count);
    ASSERT_LT((n.mean - mean).norm(), 1e-9) << "node " << id;
  }
  for (unsigned o = 0; o < 8 && !n.isLeaf(); ++o) {
    compareNodes(ref.children[o], tree, n.child(o), c, visited);
  }
}

void checkAgainstReference(const Cloud::Ptr& cloud, std::size_t max_points, float min_cell,
                           bool cubic) {
  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(max_points);
  octree.setMinCellSize(min_cell);
  octree.setCubicRoot(cubic);
  octree.setInputCloud(cloud);
  octree.compute();

  RefNode root;
  Eigen::Vector4f lo4, hi4;
  pcl::getMinMax3D(*cloud, lo4, hi4);
  root.lo = lo4.head<3>().cast<double>();
  root.hi = hi4.head<3>().cast<double>();
  if (cubic) root.hi = root.lo.array() + (root.hi - root.lo).maxCoeff();
  for (int i = 0; i < static_cast<int>(cloud->size()); ++i) root.points.push_back(i);
  refBuild(root, *cloud, max_points, min_cell);

  std::size_t visited = 0;
  compareNodes(root, octree.getResult(), 0, *cloud, visited);
  EXPECT_EQ(visited, octree.getNodes().size());
  // The one-pass form gives every node the same box, bit for bit.
  const std::vector<OctreeBox> boxes = octree.getResult().allBounds();
  ASSERT_EQ(boxes.size(), octree.getNodes().size());
  for (std::size_t id = 0; id < boxes.size(); ++id) {
    const OctreeBox one = octree.getNodeBounds(id);
    ASSERT_TRUE(one.min == boxes[id].min && one.max == boxes[id].max) << "node " << id;
  }
  EXPECT_THROW(octree.getNodeBounds(boxes.size()), std::out_of_range);
}

void checkInvariants(const AdaptiveOctree<pcl::PointXYZ>& octree, std::size_t n_points) {
  const OctreeStatistics& s = octree.getStatistics();
  const auto& nodes = octree.getNodes();
  EXPECT_EQ(s.points, n_points);
  EXPECT_EQ(s.internal_nodes * 8 + 1, s.total_nodes);
  EXPECT_EQ(s.leaf_nodes + s.internal_nodes, s.total_nodes);
  EXPECT_EQ(s.occupied_leaves + s.empty_leaves, s.leaf_nodes);
  EXPECT_LE(s.max_depth, kOctreeMaxDepth);
  std::vector<int> seen(n_points, 0);
  std::uint64_t leaf_sum = 0;
  for (std::size_t id = 0; id < nodes.size(); ++id) {
    if (!nodes[id].isLeaf()) continue;
    leaf_sum += nodes[id].count;
    for (int i : octree.getPointIndices(id)) ++seen[static_cast<std::size_t>(i)];
  }
  EXPECT_EQ(leaf_sum, n_points);
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int k) { return k == 1; }))
      << "some point is in no leaf or in two";
}

Cloud::Ptr load(const std::string& file) {
  auto cloud = std::make_shared<Cloud>();
  loadCloud(dataPath(file), *cloud);
  return cloud;
}

}  // namespace

TEST(AdaptiveOctree, MatchesRecursiveReferenceOnStudyScans) {
  for (const char* name : {"ciencias000", "museo000", "poli000", "poli001"}) {
    SCOPED_TRACE(name);
    auto cloud = load(std::string("ua_mapas_metricos_pcd/") + name + ".pcd");
    checkAgainstReference(cloud, 100, 1.0f, false);
    checkAgainstReference(cloud, 100, 0.5f, false);
    checkAgainstReference(cloud, 200, 1.0f, false);
    checkAgainstReference(cloud, 20, 0.1f, true);
  }
}

TEST(AdaptiveOctree, MatchesRecursiveReferenceOnPclClouds) {
  for (const char* file : {"pcl_test_pcd/bunny.pcd", "pcl_test_pcd/car6.pcd",
                           "pcl_test_pcd/cturtle.pcd", "pcl_test_pcd/octants.pcd"}) {
    SCOPED_TRACE(file);
    auto cloud = load(file);
    checkAgainstReference(cloud, 10, 0.001f, false);
    checkAgainstReference(cloud, 0, 0.01f, true);
    checkAgainstReference(cloud, 1, 0.0f, false);  // deep: stops at depth 21 at the latest
  }
}

TEST(AdaptiveOctree, InvariantsOnRealData) {
  auto cloud = load("kitti_odometry_00/sequences/00/velodyne/000000.bin");
  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(20);
  octree.setMinCellSize(0.2f);
  octree.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ> means;
  octree.filter(means);
  checkInvariants(octree, cloud->size());
  EXPECT_EQ(means.size(), octree.getStatistics().occupied_leaves);
  // Each output point is its leaf's mean and lies inside that leaf.
  const auto& leaves = octree.getOccupiedLeaves();
  for (std::size_t k = 0; k < means.size(); ++k) {
    const OctreeNode& n = octree.getNodes()[leaves[k]];
    EXPECT_FLOAT_EQ(means[k].x, static_cast<float>(n.mean.x()));
    const OctreeBox box = octree.getNodeBounds(leaves[k]);
    EXPECT_TRUE((n.mean.array() >= box.min.array() - 1e-9).all() &&
                (n.mean.array() <= box.max.array() + 1e-9).all());
  }
}

TEST(AdaptiveOctree, PointsOnMaxFacesAreKept) {
  // The study's code lost points lying on the root's max faces; here all 8 corners stay.
  auto cloud = load("pcl_test_pcd/octants.pcd");
  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setMaxPointsPerLeaf(0);
  octree.setMinCellSize(0.5f);
  octree.setInputCloud(cloud);
  octree.compute();
  checkInvariants(octree, cloud->size());
  EXPECT_EQ(octree.getStatistics().occupied_leaves, 8u);
}

TEST(AdaptiveOctree, DegenerateInputsTerminate) {
  auto same = std::make_shared<Cloud>();
  for (int i = 0; i < 1000; ++i) same->push_back(pcl::PointXYZ(1.5f, -2.0f, 3.25f));
  AdaptiveOctree<pcl::PointXYZ> octree;
  octree.setInputCloud(same);
  octree.setMaxPointsPerLeaf(0);
  octree.setMinCellSize(0.0f);
  octree.compute();  // zero extent: the root cannot split
  EXPECT_EQ(octree.getStatistics().total_nodes, 1u);
  checkInvariants(octree, same->size());

  // Two clusters of identical points far apart: splits stop at depth 21.
  auto pair = std::make_shared<Cloud>(*same);
  for (int i = 0; i < 10; ++i) pair->push_back(pcl::PointXYZ(1.5f + 1e-6f, -2.0f, 3.25f));
  octree.setInputCloud(pair);
  octree.compute();
  EXPECT_LE(octree.getStatistics().max_depth, kOctreeMaxDepth);
  checkInvariants(octree, pair->size());
  checkAgainstReference(pair, 0, 0.0f, false);
}

TEST(AdaptiveOctree, RejectsBadParameters) {
  AdaptiveOctree<pcl::PointXYZ> octree;
  for (float bad : {-1.0f, std::nanf(""), INFINITY}) {
    EXPECT_THROW(octree.setMinCellSize(bad), std::invalid_argument) << bad;
  }
  EXPECT_THROW(octree.setRootBox(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 1)),
               std::invalid_argument);
  EXPECT_THROW(octree.compute(), std::invalid_argument);  // no input
}

TEST(AdaptiveOctree, RandomCloudsMatchReference) {
  std::mt19937 rng(5);
  std::normal_distribution<float> g(0.0f, 3.0f);
  for (int trial = 0; trial < 5; ++trial) {
    auto cloud = std::make_shared<Cloud>();
    for (int i = 0; i < 4000; ++i) cloud->push_back(pcl::PointXYZ(g(rng), 0.3f * g(rng), g(rng)));
    checkAgainstReference(cloud, static_cast<std::size_t>(trial * 7), 0.05f * trial, trial % 2);
  }
}

TEST(AdaptiveOctree, FilterWithoutInputThrowsAsComputeDoes) {
  AdaptiveOctree<pcl::PointXYZ> octree;
  pcl::PointCloud<pcl::PointXYZ> out;
  EXPECT_THROW(octree.compute(), std::invalid_argument);
  EXPECT_THROW(octree.filter(out), std::invalid_argument);
}

}  // namespace metricmap
