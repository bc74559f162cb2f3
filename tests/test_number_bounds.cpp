// Numbers a file or an array may hold but the toolkit cannot use as given: float64 values beyond
// the float range points are stored in (they became inf and the point vanished), depths that
// underflow to 0, poses and angles beyond the bounds every other reader applies (a g2o theta of
// 1e17 acted as 0), LaserScan angles beyond two turns, and grid cells finer than float32
// resolves the cloud's coordinates. Each is refused with one message naming the value.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/npy_reader.h"
#include "metricmap/io/point_cloud2.h"
#include "metricmap/io/trajectory_relations.h"
#include "metricmap/posegraph/g2o_io.h"
#include "metricmap/posegraph/pose_graph.h"
#include "temp_dir.h"

namespace metricmap {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// `fn` throws E whose message contains `needle`.
template <typename E, typename Fn>
void expectRefused(Fn fn, const std::string& needle) {
  try {
    fn();
    ADD_FAILURE() << "accepted, wanted: " << needle;
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------- g2o, PoseGraph, relations

struct TextCase {
  std::string text;
  std::string needle;  ///< empty: accepted
};

TEST(NumberBounds, G2oPosesAndAnglesWithinTheBoundsOfEveryOtherPoseReader) {
  const std::string edge = " 1 0 0 1 0 1\n";  // information: identity
  const std::vector<TextCase> cases = {
      {"VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1e30 0 0\nEDGE_SE2 0 1 1 0 0" + edge, "line 2"},
      {"VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 0 -1000001 0\nEDGE_SE2 0 1 1 0 0" + edge, "line 2"},
      {"VERTEX_SE2 0 0 0 1e17\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0" + edge, "theta"},
      {"VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 1e17" + edge, "theta"},
      {"VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1e7 0 0" + edge, "line 3"},
      {"EDGE_SE2 0 1 1 0 -2e6" + edge, "theta"},
      // within the bounds: accepted
      {"VERTEX_SE2 0 1000000 -1000000 0\nVERTEX_SE2 1 1 0 1e6\nEDGE_SE2 0 1 1 0 -1e6" + edge, ""},
      {"VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 62.8\nEDGE_SE2 0 1 1 0 62.8" + edge, ""},
  };
  TempDir dir("g2o_bounds");
  for (const TextCase& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string path = dir.write("g.g2o", c.text);
    if (c.needle.empty()) {
      EXPECT_NO_THROW(readG2o2D(path));
    } else {
      expectRefused<InputError>([&] { readG2o2D(path); }, c.needle);
    }
  }
  const std::string edge3 = " 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1\n";
  const std::string bad3 =
      "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 0 0 1e30 0 0 0 1\n"
      "EDGE_SE3:QUAT 0 1 1 0 0 0 0 0 1" +
      edge3;
  expectRefused<InputError>([&] { readG2o3D(dir.write("g3.g2o", bad3)); }, "line 2");
}

TEST(NumberBounds, PoseGraphRefusesPosesBeyondTheBoundsWhereverTheyComeFrom) {
  PoseGraph2D g;
  for (const Pose2D& p : {Pose2D{1e30, 0, 0}, Pose2D{0, -1.5e6, 0}, Pose2D{0, 0, 1e17},
                          Pose2D{0, 0, -1e7}, Pose2D{kNaN, 0, 0}, Pose2D{0, 0, kInf}}) {
    SCOPED_TRACE(p.x);
    EXPECT_THROW(g.addVertex(0, p), std::invalid_argument);
  }
  EXPECT_EQ(g.vertexCount(), 0u);
  EXPECT_NO_THROW(g.addVertex(0, Pose2D{1e6, -1e6, -1e6}));
  EXPECT_NO_THROW(g.addVertex(1, Pose2D{1, 0, 0}));
  PoseGraph2D::Information info = PoseGraph2D::Information::Identity();
  EXPECT_THROW(g.addEdge(0, 1, Pose2D{0, 0, 1e17}, info), std::invalid_argument);
  EXPECT_THROW(g.addEdge(0, 1, Pose2D{2e6, 0, 0}, info), std::invalid_argument);
  EXPECT_EQ(g.edgeCount(), 0u);
  PoseGraph3D g3;
  Pose3D far;
  far.translation = Eigen::Vector3d(0, 0, 1e30);
  EXPECT_THROW(g3.addVertex(0, far), std::invalid_argument);
}

TEST(NumberBounds, RelationAnglesBeyondTheBoundAreRefused) {
  const std::vector<TextCase> cases = {
      {"0 1 0 0 0 0 0 1e30\n", "yaw"},        {"0 1 0 0 0 1e7 0 0\n", "roll"},
      {"0 1 0 0 0 0 -1e17 0\n", "pitch"},     {"0 1 0 0 0 0 0 1000001\n", "yaw"},
      {"0 1 0 0 0 0 0 3.14159\n", ""},        {"0 1 1 2 3 -1e6 1e6 6.3\n", ""},
      {"0 1 2e6 0 0 0 0 0\n", "translation"},
  };
  TempDir dir("relation_bounds");
  for (const TextCase& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string path = dir.write("r.txt", c.text);
    if (c.needle.empty()) {
      EXPECT_EQ(readRelations(path).size(), 1u);
    } else {
      expectRefused<InputError>([&] { readRelations(path); }, c.needle);
    }
  }
}

// ---------------------------------------------------------------- bag messages

/// A CDR message written field by field (little-endian, aligned as CDR aligns).
struct Cdr {
  std::vector<std::uint8_t> b{0, 1, 0, 0};
  void align(std::size_t n) {
    while ((b.size() - 4) % n) b.push_back(0);
  }
  template <typename T>
  void put(T v) {
    align(sizeof(T));
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    b.insert(b.end(), p, p + sizeof(T));
  }
  void str(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size() + 1));
    b.insert(b.end(), s.begin(), s.end());
    b.push_back(0);
  }
  void header() {
    put(std::int32_t{5});
    put(std::uint32_t{6});
    str("laser");
  }
};

std::vector<std::uint8_t> laserScan(float angle_min, float increment, std::uint32_t n) {
  Cdr c;
  c.header();
  c.put(angle_min);
  c.put(angle_min + increment * static_cast<float>(n));
  c.put(increment);
  c.put(0.0f);
  c.put(0.1f);
  c.put(0.05f);
  c.put(30.0f);
  c.put(n);
  for (std::uint32_t k = 0; k < n; ++k) c.put(2.0f);
  c.put(std::uint32_t{0});
  return c.b;
}

TEST(NumberBounds, LaserScanAnglesBeyondTwoTurnsAreRefused) {
  struct Case {
    float angle_min, increment;
    std::uint32_t n;
    bool refused;
  };
  const float pi = 3.14159265f;
  const std::vector<Case> cases = {
      {1e30f, 0.01f, 10, true},
      {0.0f, 1e30f, 3, true},
      {-1e30f, 1e30f, 2, true},
      {0.0f, 0.1f, 200, true},
      {-20.0f, 0.01f, 10, true},
      {1e30f, 0.01f, 0, true},
      {-pi, 2 * pi / 360, 360, false},
      {0.0f, 2 * pi / 720, 720, false},
      {-2 * pi, 0.1f, 100, false},
      {0.0f, 1e30f, 1, false},  // one beam: the increment is never used
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << c.angle_min << " + k " << c.increment << ", " << c.n);
    const auto m = laserScan(c.angle_min, c.increment, c.n);
    auto decode = [&] {
      return decodeLaserScan(m.data(), m.size(), MessageReader::Encoding::Cdr, "b.mcap: message 0");
    };
    if (c.refused) {
      expectRefused<InputError>(decode, "beyond +-4 pi");
    } else {
      const LaserMessage out = decode();
      ASSERT_EQ(out.scan.angles.size(), c.n);
      for (std::uint32_t k = 0; k < c.n; ++k)  // the oracle: angle_min + k increment
        EXPECT_EQ(out.scan.angles[k], double(c.angle_min) + double(k) * double(c.increment));
    }
  }
}

/// A PointCloud2 of float64 x y z intensity, one point per row of `values`.
std::vector<std::uint8_t> cloud64(const std::vector<std::array<double, 4>>& values) {
  Cdr c;
  c.header();
  c.put(std::uint32_t{1});                           // height
  c.put(static_cast<std::uint32_t>(values.size()));  // width
  c.put(std::uint32_t{4});                           // fields
  const char* names[4] = {"x", "y", "z", "intensity"};
  for (std::uint32_t f = 0; f < 4; ++f) {
    c.str(names[f]);
    c.put(8 * f);
    c.put(std::uint8_t{8});  // FLOAT64
    c.put(std::uint32_t{1});
  }
  c.put(std::uint8_t{0});  // little-endian
  c.put(std::uint32_t{32});
  c.put(static_cast<std::uint32_t>(32 * values.size()));
  c.put(static_cast<std::uint32_t>(32 * values.size()));
  for (const auto& v : values) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(v.data());
    c.b.insert(c.b.end(), p, p + 32);
  }
  c.put(std::uint8_t{1});
  return c.b;
}

TEST(NumberBounds, Float64CloudValuesBeyondTheFloatRangeAreRefusedNotDropped) {
  const double big = 1e300, edge = 3.4e38;
  struct Case {
    std::vector<std::array<double, 4>> points;
    std::string needle;  ///< empty: accepted
    std::size_t kept;
  };
  const std::vector<Case> cases = {
      {{{1, 2, 3, 0}, {big, 0, 0, 0}}, "point 1: x = 1e+300", 0},
      {{{0, -big, 0, 0}}, "point 0: y", 0},
      {{{0, 0, 3.5e38, 0}}, "point 0: z", 0},
      {{{1, 2, 3, big}}, "intensity", 0},
      {{{1, 2, 3, -1e39}}, "intensity", 0},
      {{{edge, -edge, 1e-300, 1e38}, {1, 2, 3, 4}}, "", 2},
      {{{kNaN, 0, 0, 0}, {kInf, 0, 0, 0}, {1, 2, 3, 4}}, "", 1},  // no return: dropped
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.needle);
    const auto m = cloud64(c.points);
    auto decode = [&] {
      return decodePointCloud2(m.data(), m.size(), MessageReader::Encoding::Cdr, "b.db3: m 0");
    };
    if (!c.needle.empty()) {
      expectRefused<InputError>(decode, c.needle);
    } else {
      const CloudMessage out = decode();
      ASSERT_EQ(out.cloud.points.size(), c.kept);
      const auto& last = c.points.back();  // the oracle: the values cast to float
      EXPECT_EQ(out.cloud.points.back().x, static_cast<float>(last[0]));
      EXPECT_EQ(out.cloud.intensity.back(), static_cast<float>(last[3]));
    }
  }
}

/// A float64 (rows, cols) .npy array.
std::string writeNpy64(const TempDir& dir, const std::vector<double>& v, std::size_t cols) {
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" +
                       std::to_string(v.size() / cols) + ", " + std::to_string(cols) + "), }";
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  const std::string path = dir / "a.npy";
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const auto len = static_cast<std::uint16_t>(header.size());
  out.write(reinterpret_cast<const char*>(&len), 2);
  out << header;
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(8 * v.size()));
  return path;
}

TEST(NumberBounds, Float64NpyValuesBeyondTheFloatRangeAreRefused) {
  TempDir dir("npy_bounds");
  expectRefused<InputError>(
      [&] {
        readNpyPoints(writeNpy64(dir, {1, 2, 3, 1e300, 0, 0}, 3));
      },
      "row 1 column 0 (x) holds 1e+300");
  expectRefused<InputError>(
      [&] {
        readNpyPoints(writeNpy64(dir, {1, 2, -1e39, 4}, 4));
      },
      "column 2 (z)");
  expectRefused<InputError>(
      [&] {
        readNpyPoints(writeNpy64(dir, {1, 2, 3, 1e300}, 4));
      },
      "column 3 (i)");
  // A fifth column is not read as a point value: any finite double is kept as given.
  const NpyArray a = readNpyPoints(writeNpy64(dir, {1, 2, 3, 4, 1e300}, 5));
  EXPECT_EQ(a.values[4], 1e300);
  EXPECT_EQ(readNpyPoints(writeNpy64(dir, {3.4e38, 1e-300, kNaN}, 3)).values[0], 3.4e38);
}

// ---------------------------------------------------------------- depth images

TEST(NumberBounds, DepthScalesThatUnderflowToZeroAreRefused) {
  DepthImage depth;
  depth.width = 4;
  depth.height = 2;
  depth.values = {0, 1, 1000, 65535, 7, 0, 2, 3};
  CameraIntrinsics k{500, 500, 2, 1, 4, 2, 0};
  struct Case {
    double scale;
    bool refused;
  };
  for (const Case& c : std::vector<Case>{{1e-300, true},
                                         {1e-40, true},  // depth 1 -> 1e-40 m: a subnormal
                                         {1.2e-38, false},
                                         {1e-3, false},
                                         {1e-9, false}}) {
    SCOPED_TRACE(c.scale);
    if (c.refused) {
      expectRefused<std::invalid_argument>([&] { depthToCloud(depth, k, c.scale); },
                                           "below float range");
    } else {
      const auto cloud = depthToCloud(depth, k, c.scale);
      EXPECT_EQ(cloud[2].z, static_cast<float>(1000 * c.scale));  // the oracle: d * scale
    }
  }
}

// ---------------------------------------------------------------- grid cells

TEST(NumberBounds, GridCellsFinerThanFloatResolvesTheCoordinatesAreRefused) {
  struct Case {
    float x0, x1, cell;
    bool refused;
  };
  const std::vector<Case> cases = {
      {1e7f, 10000001.0f, 0.1f, true},  {1e7f, 10000001.0f, 1.0f, true},
      {-1e7f, 1e7f, 0.5f, true},        {1e7f, 10000012.0f, 8.0f, false},
      {1000.0f, 1001.05f, 0.1f, false}, {0.0f, 100.0005f, 0.001f, false},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << c.x0 << " .. " << c.x1 << " at " << c.cell);
    auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    cloud->push_back({c.x0, 0, 0});
    cloud->push_back({c.x1, 0, 0});
    OccupancyGrid<pcl::PointXYZ> grid;
    grid.setInputCloud(cloud);
    grid.setCellSize(c.cell);
    pcl::PointCloud<pcl::PointXYZ> means;
    if (c.refused) {
      expectRefused<CapacityError>([&] { grid.filter(means); }, "finer than float32 resolves");
      // World-aligned cells need no snapping: floor(p / cell) in float, as pcl::VoxelGrid.
      grid.setOrigin(GridOrigin::WorldAligned);
      grid.filter(means);
      ASSERT_EQ(grid.getCells().size(), c.x0 == c.x1 ? 1u : 2u);
      const float inv = 1.0f / c.cell;
      EXPECT_EQ(grid.getCells().front().index[0],
                static_cast<std::int64_t>(std::floor(c.x0 * inv)));
    } else {
      grid.filter(means);
      ASSERT_FALSE(grid.getCells().empty());
      // The cloud's minimum is in cell 0; the maximum's cell is floor((x1 - x0) / cell).
      EXPECT_EQ(grid.getCells().front().index[0], 0);
      EXPECT_EQ(grid.getCells().back().index[0],
                static_cast<std::int64_t>(std::floor((double(c.x1) - c.x0) / c.cell)));
    }
  }
}

}  // namespace
}  // namespace metricmap
