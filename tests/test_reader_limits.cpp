// Readers on damaged and hostile files: each is refused with InputError naming the file, and
// valid edge cases (a one-row depth image) give the pinhole model's values.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/laser_scan.h"
#include "scratch_files.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;
const std::string kRegress = std::string(METRICMAP_SOURCE_DIR) + "/tests/fuzz_regressions/";

const test_support::ScratchDir kScratch("metricmap_hard_");
std::string writeTemp(const std::string& name, const std::string& text) {
  return kScratch.write(name, text);
}
using test_support::inputErrorOf;

}  // namespace

TEST(ReaderLimits, CarmenBeamCountsMustBeSmallIntegers) {
  const std::string m = inputErrorOf([] { readCarmenLog(kRegress + "carmen_flaser_1e20.log"); });
  EXPECT_NE(m.find("no scan found (2 malformed"), std::string::npos) << m;
  // the same lines with honest counts are scans
  const std::string ok =
      writeTemp("ok.log", "FLASER 3 1 2 3\nROBOTLASER1 0 -1.57 3.14 0.01 80 0.1 0 3 1 2 3\n");
  const ScanLog log = readCarmenLog(ok);
  ASSERT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.scans[0].ranges, (std::vector<double>{1.0, 2.0, 3.0}));
  for (const char* n : {"0x3", "3.0", "-3", "4", "1e1"}) {
    const std::string p = writeTemp("bad.log", std::string("FLASER ") + n + " 1 2 3\n");
    EXPECT_THROW(readCarmenLog(p), InputError) << n;
  }
}

TEST(ReaderLimits, PlyAndPcdLayoutsPclCannotTake) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const char* f :
       {"ply_list_before_xyz.ply", "ply_obj_info_negative_cols.ply", "ply_zero_vertices.ply",
        "pcd_width_0.pcd", "pcd_compressed_declares_357913941.pcd"}) {
    const std::string m = inputErrorOf([&] { loadCloud(kRegress + f, cloud); });
    EXPECT_NE(m.find(f), std::string::npos) << m;
  }
  const std::string empty_bin = writeTemp("empty.bin", "");
  EXPECT_THROW(loadCloud(empty_bin, cloud), InputError);
  const fs::path dir =
      fs::temp_directory_path() / ("metricmap_hard_dir_" + std::to_string(::getpid()) + ".bin");
  fs::create_directories(dir);
  EXPECT_NE(inputErrorOf([&] { loadCloud(dir.string(), cloud); }).find("not a regular file"),
            std::string::npos);
  fs::remove(dir);
  // hex and beyond-float values in an ascii body are not numbers PCL reads as we do
  const std::string hdr =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\n"
      "POINTS 1\nDATA ascii\n";
  EXPECT_THROW(loadCloud(writeTemp("hex.pcd", hdr + "0x10 1 2\n"), cloud), InputError);
  EXPECT_THROW(loadCloud(writeTemp("big.pcd", hdr + "1e39 1 2\n"), cloud), InputError);
  loadCloud(writeTemp("fine.pcd", hdr + "1.5 -2 3e2\n"), cloud);
  ASSERT_EQ(cloud.size(), 1u);
  EXPECT_EQ(cloud[0].z, 300.0f);
}

TEST(ReaderLimits, CameraFilesCheckEveryNumber) {
  EXPECT_THROW(readCameraFile(kRegress + "camera_z_factor_abc.xml"), InputError);
  EXPECT_THROW(readCameraFile(kRegress + "camera_deep.json"), InputError);
  std::ifstream in(kRegress + "camera_z_factor_abc.xml");
  const std::string xml((std::istreambuf_iterator<char>(in)), {});
  for (const char* v : {"nan", "-0.001", "0", "0x10", "1e999", ""}) {
    std::string text = xml;
    text.replace(text.find(">abc<") + 1, 3, v);
    EXPECT_THROW(readCameraFile(writeTemp("cam.xml", text)), InputError) << v;
  }
  std::string good = xml;
  good.replace(good.find(">abc<") + 1, 3, "0.002");
  const CameraIntrinsics k = readCameraFile(writeTemp("cam.xml", good));
  EXPECT_EQ(k.depth_scale, 0.002);
  EXPECT_EQ(k.fx, 525.0);
  for (const char* t : {"525,525,319.5", "525,525,319.5,239.5,1", "0,525,1,1", ",525,1,1", ""})
    EXPECT_THROW(parseIntrinsics(t), std::invalid_argument) << t;
}

TEST(ReaderLimits, OneRowDepthImageAndFloatRange) {
  DepthImage d;
  d.width = 4;
  d.height = 1;
  d.values = {1000, 2000, 0, 3000};
  CameraIntrinsics k;
  k.fx = 500.0;
  k.fy = 400.0;
  k.cx = 1.5;
  k.cy = 0.0;
  const auto cloud = depthToCloud(d, k, 0.001);
  ASSERT_EQ(cloud.width, 4u);
  ASSERT_EQ(cloud.height, 1u);
  for (int u = 0; u < 4; ++u) {
    if (d.values[u] == 0) {
      EXPECT_TRUE(std::isnan(cloud[u].z));
      continue;
    }
    const double z = d.values[u] * 0.001;
    EXPECT_FLOAT_EQ(cloud[u].x, static_cast<float>((u - 1.5) * z / 500.0));
    EXPECT_FLOAT_EQ(cloud[u].y, 0.0f);
    EXPECT_FLOAT_EQ(cloud[u].z, static_cast<float>(z));
  }
  EXPECT_THROW(depthToCloud(d, k, 1e300), std::invalid_argument);
}

}  // namespace metricmap
