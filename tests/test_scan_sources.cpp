// Scan sources: folders of scan files (natural order, stamps, reference poses, per-point times),
// the KITTI layout, and their refusals; checked against PCL's own reader and plain parses of the
// text files written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>

#include "metricmap/datasets/folder_source.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/scan_file.h"
#include "temp_dir.h"

namespace fs = std::filesystem;
using metricmap::InputError;

namespace {

const std::string kBalm = std::string(METRICMAP_SHARED_DATA_DIR) + "/balm_realworld_dev";
const std::string kVlp16 =
    std::string(METRICMAP_SHARED_DATA_DIR) + "/nebula_driver_samples/vlp16_1673400472138016708.pcd";

std::vector<std::vector<double>> numberRows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream is(line);
    std::vector<double> row;
    double v;
    while (is >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// A minimal binary PCD with x y z and one extra field of the given PCD type/size.
void writePcdWithField(const fs::path& p, const char* field, char type, int size, int points) {
  std::ofstream out(p, std::ios::binary);
  out << "VERSION 0.7\nFIELDS x y z " << field << "\nSIZE 4 4 4 " << size << "\nTYPE F F F " << type
      << "\nCOUNT 1 1 1 1\nWIDTH " << points << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS "
      << points << "\nDATA binary\n";
  for (int i = 0; i < points; ++i) {
    const float xyz[3] = {static_cast<float>(i), 1.0f, 2.0f};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const std::uint64_t v = static_cast<std::uint64_t>(i) * 1000;
    out.write(reinterpret_cast<const char*>(&v), size);  // little-endian low bytes
  }
}

}  // namespace

TEST(NaturalOrder, NumbersCompareByValue) {
  std::vector<std::string> names = {"scan10.pcd", "scan2.pcd", "scan1.pcd",
                                    "scan02.pcd", "a.pcd",     "scan100.pcd"};
  std::sort(names.begin(), names.end(), metricmap::naturalLess);
  const std::vector<std::string> want = {"a.pcd",      "scan1.pcd",  "scan2.pcd",
                                         "scan02.pcd", "scan10.pcd", "scan100.pcd"};
  EXPECT_EQ(names, want);
  EXPECT_FALSE(metricmap::naturalLess("x", "x"));
}

TEST(FolderSource, BalmFolderMatchesPclAndItsTextFiles) {
  auto source = metricmap::openScanSource(kBalm);
  const metricmap::SourceInfo& info = source->info();
  EXPECT_EQ(info.kind, "folder");
  ASSERT_EQ(source->size(), 40u);
  // Stamps and reference poses as a plain parse of the files reads them.
  const auto times = numberRows(kBalm + "/times.txt");
  const auto poses = numberRows(kBalm + "/poses.txt");
  ASSERT_EQ(info.stamps.size(), 40u);
  ASSERT_EQ(info.reference.size(), 40u);
  for (std::size_t i = 0; i < 40; ++i) {
    EXPECT_DOUBLE_EQ(info.stamps[i], times[i][0]);
    for (int k = 0; k < 12; ++k) {
      EXPECT_NEAR(info.reference.poses[i].matrix()(k / 4, k % 4), poses[i][k], 1e-12);
    }
  }
  // Scan 10 is full66.pcd (natural order from full56), point for point as PCL reads it.
  const metricmap::Scan s = source->scan(10);
  EXPECT_EQ(fs::path(s.name).filename(), "full66.pcd");
  EXPECT_DOUBLE_EQ(s.stamp, times[10][0]);
  pcl::PointCloud<pcl::PointXYZI> pcl_cloud;
  ASSERT_EQ(pcl::io::loadPCDFile(kBalm + "/full66.pcd", pcl_cloud), 0);
  ASSERT_EQ(s.points.size(), pcl_cloud.size());
  ASSERT_EQ(s.intensity.size(), pcl_cloud.size());
  for (std::size_t i = 0; i < pcl_cloud.size(); i += 97) {
    EXPECT_EQ(s.points[i].x, pcl_cloud[i].x);
    EXPECT_EQ(s.points[i].z, pcl_cloud[i].z);
    EXPECT_EQ(s.intensity[i], pcl_cloud[i].intensity);
  }
  EXPECT_TRUE(s.point_times.empty());
  EXPECT_FALSE(info.point_times);
  // Backwards works too.
  EXPECT_EQ(fs::path(source->scan(0).name).filename(), "full56.pcd");
  EXPECT_THROW(source->scan(40), InputError);
}

TEST(ScanFile, Vlp16TimeStampFieldInNanoseconds) {
  const metricmap::ScanFile f = metricmap::readScanFile(kVlp16);
  EXPECT_EQ(f.time_field, "time_stamp");
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ(pcl::io::loadPCDFile(kVlp16, blob), 0);
  int at = -1;
  for (const auto& field : blob.fields) {
    if (field.name == "time_stamp") at = static_cast<int>(field.offset);
  }
  ASSERT_GE(at, 0);
  std::vector<std::uint32_t> raw(blob.width * blob.height);
  for (std::size_t i = 0; i < raw.size(); ++i) {
    std::memcpy(&raw[i], blob.data.data() + i * blob.point_step + at, 4);
  }
  ASSERT_EQ(f.point_times.size(), f.points.size());
  ASSERT_EQ(f.points.size() + f.nonfinite_dropped, raw.size());
  // SOURCE.md: the field runs from 2 303 to 1 306 368 (ns).
  const double span = *std::max_element(f.point_times.begin(), f.point_times.end());
  EXPECT_NEAR(span, (1306368.0 - 2303.0) * 1e-9, 1e-12);
  EXPECT_EQ(*std::min_element(f.point_times.begin(), f.point_times.end()), 0.0);
  if (f.nonfinite_dropped == 0) {
    for (std::size_t i = 0; i < raw.size(); i += 101) {
      EXPECT_NEAR(f.point_times[i], (raw[i] - 2303.0) * 1e-9, 1e-15);
    }
  }
}

TEST(FolderSource, PerPointTimesAndTheirRefusals) {
  TempDir tmp("scan_times");
  const fs::path d = tmp.path / "t";
  fs::create_directories(d);
  writePcdWithField(d / "0.pcd", "t", 'U', 4, 200);
  writePcdWithField(d / "1.pcd", "t", 'U', 4, 200);
  auto source = metricmap::openScanSource(d.string());
  EXPECT_TRUE(source->info().point_times);
  const metricmap::Scan s = source->scan(1);
  ASSERT_EQ(s.point_times.size(), 200u);
  EXPECT_NEAR(s.point_times[199], 199 * 1000 * 1e-9, 1e-15);  // uint32 read as ns

  const fs::path bad = tmp.path / "u8";
  fs::create_directories(bad);
  writePcdWithField(bad / "0.pcd", "time", 'U', 1, 50);
  try {
    metricmap::openScanSource(bad.string());
    FAIL() << "a uint8 time field was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("0.pcd"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'time'"), std::string::npos) << e.what();
  }
}

TEST(FolderSource, RefusesInconsistentFolders) {
  TempDir tmp("scan_folders");
  auto expectRefused = [](const fs::path& dir, const std::string& needle) {
    try {
      metricmap::openScanSource(dir.string());
      ADD_FAILURE() << dir << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  const fs::path empty = tmp.path / "empty";
  fs::create_directories(empty);
  writeText(empty / "notes.txt", "no scans here\n");
  expectRefused(empty, "no .pcd, .ply, .bin or .npy scan");

  const fs::path mixed = tmp.path / "mixed";
  fs::create_directories(mixed);
  fs::copy_file(kBalm + "/full56.pcd", mixed / "a.pcd");
  fs::copy_file(fs::path(METRICMAP_DATA_DIR) / "kitti_odometry_00/sequences/00/velodyne/000000.bin",
                mixed / "b.bin");
  expectRefused(mixed, "mixed scan formats");

  const fs::path two = tmp.path / "two";
  fs::create_directories(two);
  fs::copy_file(kBalm + "/full56.pcd", two / "a.pcd");
  fs::copy_file(kBalm + "/full57.pcd", two / "b.pcd");
  writeText(two / "times.txt", "1.0\n");
  expectRefused(two, "1 stamp(s) for 2 scan(s)");
  writeText(two / "times.txt", "2.0\n1.0\n");
  expectRefused(two, "is not after the one before");
  writeText(two / "times.txt", "1.0\n2.0\n");
  writeText(two / "poses.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
  expectRefused(two, "1 pose line(s) for 2 scan(s)");
  writeText(two / "poses.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n");
  expectRefused(two, "poses.txt");
  fs::remove(two / "poses.txt");
  EXPECT_EQ(metricmap::openScanSource(two.string())->size(), 2u);
}

TEST(KittiSource, ReferenceInTheVelodyneFrameAndStamps) {
  const std::string root = std::string(METRICMAP_DATA_DIR) + "/kitti_odometry_00";
  auto source = metricmap::openScanSource(root);
  EXPECT_EQ(source->info().kind, "kitti");
  ASSERT_EQ(source->size(), 6u);
  const Eigen::Isometry3d tr = metricmap::readKittiCalibTr(root + "/sequences/00/calib.txt");
  const auto cam = metricmap::readKittiPoses(root + "/poses/00.txt", 6);
  const auto times = numberRows(root + "/sequences/00/times.txt");
  for (std::size_t i = 0; i < 6; ++i) {
    // Tr^-1 P Tr, computed here with a general inverse.
    const Eigen::Matrix4d want = tr.matrix().inverse() * cam[i].matrix() * tr.matrix();
    EXPECT_TRUE(source->info().reference.poses[i].matrix().isApprox(want, 1e-9)) << i;
    EXPECT_DOUBLE_EQ(source->info().stamps[i], times[i][0]);
  }
  EXPECT_THROW(source->scan(6), InputError);
  EXPECT_GT(source->scan(5).points.size(), 100000u);
}
