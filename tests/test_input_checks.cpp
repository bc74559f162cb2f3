// Issue 24, the last adversarial findings, at the library level: CARMEN beam counts that disagree
// with the line, ranges beyond any laser, a PCD VIEWPOINT that is not a rotation, .npy clouds in
// loadCloud, relation files naming a pair twice or one stamp twice, a near-collinear rigid
// alignment, the pose-graph solver's memory, one input named twice, frame numbers with a leading
// zero.
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/datasets/folder_source.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/evaluation/alignment.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/file_identity.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/trajectory_relations.h"
#include "metricmap/posegraph/optimize.h"
#include "scratch_files.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

const test_support::ScratchDir kScratch("metricmap_h4_");
std::string writeTemp(const std::string& name, const std::string& text) {
  return kScratch.write(name, text);
}
using test_support::inputErrorOf;

std::string flaser(int declared, int given, const std::string& tail) {
  std::string line = "FLASER " + std::to_string(declared);
  for (int i = 0; i < given; ++i) line += " 2.5";
  return line + " " + tail + "\n";
}

TEST(InputChecks, CarmenBeamCountMustMatchTheLine) {
  const std::string full = "0 0 0 0 0 0 1.5 host 1.5";
  EXPECT_EQ(readCarmenLog(writeTemp("ok.clf", flaser(180, 180, full))).scans.size(), 1u);
  EXPECT_EQ(readCarmenLog(writeTemp("poses.clf", flaser(180, 180, "0 0 0 0 0 0"))).scans.size(),
            1u);
  // One beam fewer or more than declared: never ranges and poses shifted by one.
  for (const auto& [declared, given, tail] :
       {std::tuple{180, 179, full}, std::tuple{180, 181, full},
        std::tuple{180, 181, std::string("0 0 0 0 0 0")},
        std::tuple{180, 179, std::string("0 0 0 0 0 0 1.5 host")},
        std::tuple{180, 180, std::string("0 0 0 0 0 0 1.5 2.5 3.5")}}) {
    const std::string p = writeTemp("bad.clf", flaser(declared, given, tail));
    EXPECT_NE(inputErrorOf([&] { readCarmenLog(p); }).find("no scan found (1 malformed"),
              std::string::npos)
        << declared << " " << given << " " << tail;
  }
}

TEST(InputChecks, RangesBeyondAnyLaserAreNoReturn) {
  const ScanLog c =
      readCarmenLog(writeTemp("far.clf", "FLASER 3 1e39 2.0 20000 0 0 0 0 0 0 1.5 host 1.5\n"));
  ASSERT_EQ(c.scans.size(), 1u);
  EXPECT_TRUE(std::isnan(c.scans[0].ranges[0]));
  EXPECT_DOUBLE_EQ(c.scans[0].ranges[1], 2.0);
  EXPECT_TRUE(std::isnan(c.scans[0].ranges[2]));
  const ScanLog s = readAngleRangeCsv(writeTemp("far.csv", "0,1e39\n0.1,1\n0.2,1e300\n"));
  ASSERT_EQ(s.scans.size(), 1u);
  EXPECT_TRUE(std::isnan(s.scans[0].ranges[0]));
  EXPECT_DOUBLE_EQ(s.scans[0].ranges[1], 1.0);
  EXPECT_TRUE(std::isnan(s.scans[0].ranges[2]));
}

std::string pcdWithViewpoint(const std::string& viewpoint) {
  return "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\n"
         "HEIGHT 1\nVIEWPOINT " +
         viewpoint + "\nPOINTS 1\nDATA ascii\n1 2 3\n";
}

TEST(InputChecks, ViewpointQuaternionMustBeARotation) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const std::string bad = writeTemp("vp2.pcd", pcdWithViewpoint("0 0 0 2 0 0 0"));
  const std::string msg = inputErrorOf([&] { loadCloud(bad, cloud); });
  EXPECT_NE(msg.find(bad + ": VIEWPOINT quaternion (2 0 0 0) has norm 2"), std::string::npos)
      << msg;
  // six digits, as PCL writes them: read
  EXPECT_NO_THROW(
      loadCloud(writeTemp("vp6.pcd", pcdWithViewpoint("0 0 0 0.707107 0 0 0.707107")), cloud));
}

TEST(InputChecks, NpyCloudsAreReadByLoadCloud) {
  std::string hdr = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 4), }";
  hdr += std::string(64 - (10 + hdr.size() + 1) % 64, ' ') + "\n";
  std::string bytes = std::string("\x93NUMPY\x01\x00", 8);
  bytes += static_cast<char>(hdr.size() & 0xff);
  bytes += static_cast<char>(hdr.size() >> 8);
  bytes += hdr;
  const float v[8] = {1, 2, 3, 7, 4, 5, 6, 8};
  bytes.append(reinterpret_cast<const char*>(v), sizeof v);
  const std::string p = writeTemp("c.npy", bytes);
  pcl::PointCloud<pcl::PointXYZI> cloud;
  const LoadReport r = loadCloud(p, cloud);
  EXPECT_EQ(r.format, "npy");
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_FLOAT_EQ(cloud[1].x, 4.0f);
  EXPECT_FLOAT_EQ(cloud[1].intensity, 8.0f);
}

TEST(InputChecks, RelationsNameTwoStampsOnce) {
  const std::string same = writeTemp("same.txt", "1 1 1 0 0 0 0 0\n");
  EXPECT_NE(inputErrorOf([&] { readRelations(same); }).find("line 1: t1 and t2 are the same"),
            std::string::npos);
  const std::string dup =
      writeTemp("dup.txt", "0 1 1 0 0 0 0 0\n1 2 1 0 0 0 0 0\n1 0 1 0 0 0 0 0\n");
  EXPECT_NE(inputErrorOf([&] { readRelations(dup); })
                .find("line 3: the stamps '1' and '0' are "
                      "related again (line 1)"),
            std::string::npos);
  EXPECT_EQ(readRelations(writeTemp("ok.txt", "0 1 1 0 0 0 0 0\n1 2 1 0 0 0 0 0\n")).size(), 2u);
}

std::vector<Eigen::Isometry3d> positions(const std::vector<Eigen::Vector3d>& p) {
  std::vector<Eigen::Isometry3d> out;
  for (const Eigen::Vector3d& t : p) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = t;
    out.push_back(pose);
  }
  return out;
}

TEST(InputChecks, NearlyCollinearPathsAreNotRotatedByNoise) {
  std::vector<Eigen::Vector3d> ref, est, turn, turn_est;
  for (int i = 0; i < 20; ++i) {
    ref.emplace_back(i, 1e-4 * std::cos(5.0 * i), 1e-4 * std::sin(11.0 * i));
    est.emplace_back(i, 1e-4 * std::sin(7.0 * i), 1e-4 * std::cos(3.0 * i));
    turn.emplace_back(i, 0.05 * i * i, 0);  // a gentle curve: well determined
    turn_est.emplace_back(i + 0.001 * std::sin(5.0 * i), 0.05 * i * i, 0.001 * std::cos(2.0 * i));
  }
  try {
    alignPositions(positions(est), positions(ref), AlignmentMode::Rigid);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nearly collinear"), std::string::npos) << e.what();
  }
  const Alignment a = alignPositions(positions(turn_est), positions(turn), AlignmentMode::Rigid);
  EXPECT_LT(Eigen::AngleAxisd(a.rotation).angle(), 1e-3);
}

TEST(InputChecks, PoseGraphSolverIsPricedAgainstTheBudget) {
  PoseGraph2D g;
  for (int i = 0; i < 2000; ++i) g.addVertex(i, Pose2D{static_cast<double>(i), 0.0, 0.0});
  for (std::size_t i = 1; i < 2000; ++i)
    g.addEdge(i - 1, i, Pose2D{1.0, 0.0, 0.0}, PoseGraph2D::Information::Identity());
  EXPECT_EQ(jacobianNonzeros(g), 1999u * 18u);
  EXPECT_GT(solverMemoryBytes(g), 2000u * 1000u);
  const std::uint64_t budget = memoryBudget();
  setMemoryBudget(1 << 20);  // 1 MiB: below the estimate (about 4 MiB)
  EXPECT_THROW(optimize(g), CapacityError);
  setMemoryBudget(budget);
  EXPECT_EQ(optimize(g).termination, PoseGraphTermination::Converged);
}

TEST(InputChecks, RepeatedInputsByIdentity) {
  const std::string a = writeTemp("a.pcd", "x");
  const std::string b = writeTemp("b.pcd", "y");
  const std::string dotted = (kScratch.path / "." / "a.pcd").string();
  EXPECT_FALSE(findRepeatedInput({{"input", a}, {"input", b}}));
  const auto r = findRepeatedInput({{"input", a}, {"input", b}, {"input", dotted}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->first.second, a);
  EXPECT_EQ(r->second.second, dotted);
  // a list naming one scan twice
  const std::string list = writeTemp("list.txt", "a.pcd\n" + a + "\n");
  EXPECT_NE(inputErrorOf([&] { folderScanPaths(list); })
                .find("line 2 ('" + a +
                      "') names the scan "
                      "of line 1 ('a.pcd') again"),
            std::string::npos);
}

TEST(InputChecks, FrameNumbersWithALeadingZeroAreRefused) {
  EXPECT_THROW(parseFrameList("010"), std::invalid_argument);
  EXPECT_THROW(parseFrameList("0-05"), std::invalid_argument);
  EXPECT_EQ(parseFrameList("0,10").size(), 2u);
}

TEST(InputChecks, SourceKindWithoutOpening) {
  EXPECT_EQ(scanSourceKind(writeTemp("x.clf", ""), "auto"), "carmen");
  EXPECT_EQ(scanSourceKind(kScratch.path.string(), "auto"), "folder");
  EXPECT_EQ(scanSourceKind((kScratch.path / "none").string(), "auto"), "");
}

}  // namespace
}  // namespace metricmap
