// Checked writers and readers: the ASCII PCD writer is byte-identical
// to PCL's (the oracle) but reports a full disk; messages name destinations, not temporaries;
// special files are never read.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>

#include "metricmap/exceptions.h"
#include "metricmap/io/checked_file.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/input_file.h"

#include "temp_dir.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

template <typename PointT>
void expectSameAsciiAsPcl(const pcl::PointCloud<PointT>& cloud, const std::string& name) {
  TempDir dir("checked");
  pcl::PCDWriter pcl_writer;
  ASSERT_EQ(pcl_writer.writeASCII(dir / "pcl.pcd", cloud, 8), 0);
  savePcdAtomic(dir / "ours.pcd", cloud, PcdFormat::Ascii);
  EXPECT_EQ(bytesOf(dir / "ours.pcd"), bytesOf(dir / "pcl.pcd")) << name;
}

TEST(CheckedWriters, AsciiPcdIsByteIdenticalToPclsWriter) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1e4f, 1e4f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ> xyz;
  for (int i = 0; i < 500; ++i) xyz.push_back({u(rng), u(rng) * 1e-6f, u(rng) * 1e6f});
  xyz.push_back({nan, 0.0f, -0.0f});
  xyz.push_back({1e-38f, 3.4e38f, 0.1f});
  expectSameAsciiAsPcl(xyz, "PointXYZ");
  pcl::PointCloud<pcl::PointXYZI> xyzi;
  for (int i = 0; i < 200; ++i) {
    pcl::PointXYZI p;
    p.x = u(rng);
    p.y = u(rng);
    p.z = nan;
    p.intensity = u(rng);
    xyzi.push_back(p);
  }
  expectSameAsciiAsPcl(xyzi, "PointXYZI");
  pcl::PointCloud<pcl::PointXYZRGB> rgb;
  for (int i = 0; i < 200; ++i) {
    pcl::PointXYZRGB p(static_cast<std::uint8_t>(i), 255, static_cast<std::uint8_t>(3 * i));
    p.x = u(rng);
    p.y = u(rng);
    p.z = u(rng);
    rgb.push_back(p);
  }
  expectSameAsciiAsPcl(rgb, "PointXYZRGB (rgb as an integer)");
  expectSameAsciiAsPcl(pcl::PointCloud<pcl::PointXYZ>(), "empty cloud");
  pcl::PointCloud<pcl::PointXYZ> organized(3, 2, pcl::PointXYZ(1, 2, 3));
  expectSameAsciiAsPcl(organized, "organized 3 x 2");
}

TEST(CheckedWriters, AFullDeviceFailsTheWriteOrTheCloseNamingThePath) {
  CheckedFile small("/dev/full");  // a few bytes stay in the buffer until close()
  small.write("x");
  try {
    small.close();
    FAIL() << "close() on /dev/full succeeded";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/full: cannot write (No space left on device)");
  }
  CheckedFile big("/dev/full");  // a block larger than the buffer is written at once
  EXPECT_THROW(big.write(std::string(3 << 20, 'x')), std::runtime_error);
}

TEST(CheckedWriters, MessagesNameTheDestinationNotATemporary) {
  const std::string pid = std::to_string(::getpid());
  EXPECT_EQ(outputDisplayName("out/m.tmp-" + pid + "-3.pcd"), "out/m.pcd");
  EXPECT_EQ(outputDisplayName("out/m.tmp-" + pid + "-3.pcd.tmp-" + pid + "-17"), "out/m.pcd");
  EXPECT_EQ(outputDisplayName("m.tmp-" + pid + "-0"), "m");
  EXPECT_EQ(outputDisplayName("run.tmp-1/m.pcd"), "run.tmp-1/m.pcd");  // not ours: kept
  EXPECT_EQ(outputDisplayName("m.tmp-" + pid + "-.pcd"), "m.tmp-" + pid + "-.pcd");
}

TEST(CheckedWriters, WriteFailuresLeaveNothing) {
  TempDir dir("checked");
  fs::create_directories(dir / "ro");
  ::chmod((dir / "ro").c_str(), 0555);
  if (::geteuid() != 0) {  // root writes anyway
    pcl::PointCloud<pcl::PointXYZ> cloud(4, 1, pcl::PointXYZ(1, 2, 3));
    for (PcdFormat f : {PcdFormat::Ascii, PcdFormat::Binary, PcdFormat::BinaryCompressed}) {
      try {
        savePcdAtomic(dir / "ro/c.pcd", cloud, f);
        ADD_FAILURE() << "wrote into a read-only directory";
      } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(dir / "ro/c.pcd: cannot write", 0), 0u) << e.what();
      }
    }
    EXPECT_TRUE(fs::is_empty(dir / "ro"));
  }
  ::chmod((dir / "ro").c_str(), 0755);
}

TEST(CheckedReaders, SpecialFilesAreRefusedBeforeTheyAreOpened) {
  TempDir dir("checked");
  ASSERT_EQ(::mkfifo((dir / "f.bt").c_str(), 0600), 0);
  for (const std::string& path : {dir / "f.bt", std::string("/dev/zero"), dir.path.string()}) {
    try {
      readRegularFile(path, 1 << 20);
      ADD_FAILURE() << path << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
    }
    EXPECT_THROW(openRegularFile(path), InputError);
  }
  std::ofstream(dir / "small.txt") << "hello";
  EXPECT_EQ(readRegularFile(dir / "small.txt", 5), "hello");
  EXPECT_THROW(readRegularFile(dir / "small.txt", 4), CapacityError);
}

}  // namespace
}  // namespace metricmap
