// PCD headers with WIDTH 0 HEIGHT 0 and a valid POINTS n, as real pipelines write them (the
// NCLT keyframes' original headers): read as an unorganised cloud of n points with one warning.
// The oracle is PCL's own reader on the same body with the header saying WIDTH n HEIGHT 1.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "temp_dir.h"

namespace metricmap {
namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `text` with its first "from" replaced by "to".
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Ours on `zero` (WIDTH 0 HEIGHT 0) against PCL's on `fixed` (WIDTH n HEIGHT 1).
void expectSameAsFixed(const std::string& zero, const std::string& fixed, std::size_t n) {
  pcl::PointCloud<pcl::PointXYZI> ours, theirs;
  const LoadReport report = loadCloud(zero, ours);
  ASSERT_EQ(pcl::io::loadPCDFile(fixed, theirs), 0);
  ASSERT_EQ(theirs.size(), n);
  ASSERT_EQ(ours.size(), n);
  EXPECT_EQ(ours.height, 1u);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_EQ(ours[i].x, theirs[i].x) << i;
    ASSERT_EQ(ours[i].y, theirs[i].y) << i;
    ASSERT_EQ(ours[i].z, theirs[i].z) << i;
    ASSERT_EQ(ours[i].intensity, theirs[i].intensity) << i;
  }
  ASSERT_EQ(report.warnings.size(), 1u);
  const std::string& w = report.warnings[0];
  EXPECT_NE(w.find(zero), std::string::npos) << w;
  EXPECT_NE(w.find("WIDTH 0 HEIGHT 0"), std::string::npos) << w;
  EXPECT_NE(w.find("unorganised cloud of " + std::to_string(n) + " points"), std::string::npos)
      << w;
}

const char* kHead =
    "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\n"
    "COUNT 1 1 1 1\n";

TEST(PcdZeroDimensions, AsciiAndBinaryBodiesReadAsUnorganisedClouds) {
  TempDir dir("pcd_zero_dims");
  // ascii
  const std::string body = "1 2 3 4\n-1.5 0.25 8 0\n100 200 -300 7\n";
  const std::string dims = "WIDTH 0\nHEIGHT 0\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n";
  const std::string zero = dir.write("zero.pcd", kHead + dims + body);
  const std::string fixed = dir.write(
      "fixed.pcd", kHead + replaced(dims, "WIDTH 0\nHEIGHT 0", "WIDTH 3\nHEIGHT 1") + body);
  expectSameAsFixed(zero, fixed, 3);
  // binary and binary_compressed, written by PCL, then given the zero header
  pcl::PointCloud<pcl::PointXYZI> cloud;
  for (int i = 0; i < 50; ++i)
    cloud.push_back(pcl::PointXYZI(0.5f * i, -0.25f * i, 1.0f + i, static_cast<float>(i % 9)));
  for (const bool compressed : {false, true}) {
    SCOPED_TRACE(compressed);
    const std::string good = dir / "good.pcd";
    ASSERT_EQ(compressed ? pcl::io::savePCDFileBinaryCompressed(good, cloud)
                         : pcl::io::savePCDFileBinary(good, cloud),
              0);
    const std::string text = readAll(good);
    const std::string z =
        dir.write("zero_bin.pcd", replaced(text, "WIDTH 50\nHEIGHT 1", "WIDTH 0\nHEIGHT 0"));
    expectSameAsFixed(z, good, 50);
  }
}

TEST(PcdZeroDimensions, OtherInconsistentDimensionsAreStillRefused) {
  TempDir dir("pcd_zero_dims_bad");
  const std::string body = "1 2 3 4\n5 6 7 8\n";
  for (const std::string dims :
       {"WIDTH 0\nHEIGHT 1\nPOINTS 2\n", "WIDTH 2\nHEIGHT 0\nPOINTS 2\n",
        "WIDTH 0\nHEIGHT 5\nPOINTS 2\n", "WIDTH 3\nHEIGHT 1\nPOINTS 2\n"}) {
    SCOPED_TRACE(dims);
    const std::string path = dir.write("bad.pcd", kHead + dims + "DATA ascii\n" + body);
    pcl::PointCloud<pcl::PointXYZ> c;
    try {
      loadCloud(path, c);
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("differs from POINTS"), std::string::npos) << e.what();
    }
  }
}

TEST(PcdZeroDimensions, RealNcltKeyframeHeaders) {
  const std::string root =
      std::string(METRICMAP_SHARED_DATA_DIR) + "/nclt_2013_01_10_keyframes/original_headers";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << root << " is not here";
  TempDir dir("pcd_nclt");
  for (const auto& e : std::filesystem::directory_iterator(root)) {
    SCOPED_TRACE(e.path().string());
    const std::string text = readAll(e.path().string());
    const std::size_t at = text.find("\nPOINTS ");
    ASSERT_NE(at, std::string::npos);
    const std::string n = text.substr(at + 8, text.find('\n', at + 8) - at - 8);
    const std::string fixed =
        dir.write("fixed.pcd", replaced(text, "WIDTH 0\nHEIGHT 0", "WIDTH " + n + "\nHEIGHT 1"));
    expectSameAsFixed(e.path().string(), fixed, std::stoul(n));
  }
}

}  // namespace
}  // namespace metricmap
