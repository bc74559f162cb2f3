// Readers: agreement with pcl::io on good files, exact handling of the study's oddities, and a
// clear InputError (naming the file) for every kind of bad input.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <gtest/gtest.h>

#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "test_data.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

class TempDir {
 public:
  TempDir() {
    dir_ = fs::temp_directory_path() /
           ("metricmap_reader_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++));
    fs::create_directories(dir_);
  }
  ~TempDir() { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string p = (dir_ / name).string();
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }

 private:
  fs::path dir_;
  static inline int counter_ = 0;
};

void expectInputError(const std::string& path, const std::string& needle) {
  Cloud cloud;
  try {
    loadCloud(path, cloud);
    ADD_FAILURE() << path << ": loaded " << cloud.size() << " points, expected an error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find(needle), std::string::npos) << "message: " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
  }
}

const char* kPclClouds[] = {"bunny.pcd",
                            "bun0.pcd",
                            "lamppost.pcd",
                            "octants.pcd",
                            "curve_close.pcd",
                            "colored_cloud.pcd",
                            "office1_keypoints.pcd",
                            "milk.pcd",
                            "milk_color.pcd",
                            "car6.pcd",
                            "cturtle.pcd"};

}  // namespace

TEST(CloudReader, AgreesWithPclOnItsTestClouds) {
  for (const char* name : kPclClouds) {
    const std::string path = dataPath(std::string("pcl_test_pcd/") + name);
    Cloud ours, theirs;
    const LoadReport r = loadCloud(path, ours);
    ASSERT_EQ(pcl::io::loadPCDFile(path, theirs), 0) << name;
    ASSERT_EQ(ours.size(), theirs.size()) << name;
    EXPECT_EQ(r.points_in_file, theirs.size());
    EXPECT_EQ(r.nonfinite_dropped, 0u);
    for (std::size_t i = 0; i < ours.size(); ++i) {
      ASSERT_EQ(ours[i].getVector3fMap(), theirs[i].getVector3fMap()) << name << " point " << i;
    }
  }
}

TEST(CloudReader, DropsAndCountsNaN) {
  Cloud cloud;
  const LoadReport r =
      loadCloud(dataPath("pcl_test_pcd/table_scene_mug_stereo_textured.pcd"), cloud);
  EXPECT_EQ(r.format, "pcd binary_compressed");
  EXPECT_EQ(r.width, 640u);
  EXPECT_EQ(r.height, 480u);
  EXPECT_EQ(r.points_in_file, 307200u);
  EXPECT_EQ(r.nonfinite_dropped, 97920u);
  EXPECT_EQ(cloud.size(), 307200u - 97920u);
  EXPECT_TRUE(cloud.is_dense);

  // sac_plane_test.pcd has NaN normals but finite coordinates: every point stays.
  Cloud plane;
  const LoadReport p = loadCloud(dataPath("pcl_test_pcd/sac_plane_test.pcd"), plane);
  EXPECT_EQ(p.points_in_file, 3283u);
  EXPECT_EQ(p.nonfinite_dropped, 0u);
  EXPECT_EQ(plane.size(), 3283u);
}

TEST(CloudReader, DropsNaNAndInfCoordinatesInAscii) {
  TempDir tmp;
  const std::string path = tmp.write(
      "some_nan.pcd",
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\nHEIGHT 1\n"
      "POINTS 4\nDATA ascii\n1 2 3\nnan 0 0\n0 inf 0\n4 5 6\n");
  Cloud cloud;
  const LoadReport r = loadCloud(path, cloud);
  EXPECT_EQ(r.nonfinite_dropped, 2u);
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_EQ(cloud[1].x, 4.0f);
}

TEST(CloudReader, ViewpointBecomesTheSensorPoseAndBadOnesAreRefused) {
  TempDir tmp;
  const std::string head =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\n";
  Cloud cloud;
  const LoadReport r = loadCloud(
      tmp.write("vp.pcd", head + "VIEWPOINT 5 -2 1.5 0 0 0 1.005\nPOINTS 1\nDATA ascii\n1 2 3\n"),
      cloud);
  EXPECT_TRUE(r.has_viewpoint);
  EXPECT_EQ(cloud.sensor_origin_, Eigen::Vector4f(5, -2, 1.5f, 0));
  // norm 1.005, within the tolerance of 0.01: normalised, 180 deg about z
  EXPECT_NEAR(cloud.sensor_orientation_.z(), 1.0f, 1e-6f);
  EXPECT_NEAR(cloud.sensor_orientation_.w(), 0.0f, 1e-6f);
  // a quaternion of norm 2 (or 0.5) is no rotation: refused, never normalised silently
  for (const char* bad :
       {"nan 0 0 1 0 0 0", "0x10 0 0 1 0 0 0", "0 0 0 0 0 0 0", "0 0 0 1 0 0", "0 0 0 1 0 0 0 0",
        "0 0 0 1 0 0 0x", "5 -2 1.5 0 0 0 2", "0 0 0 0.5 0 0 0"}) {
    const std::string path =
        tmp.write("bad.pcd", head + "VIEWPOINT " + bad + "\nPOINTS 1\nDATA ascii\n1 2 3\n");
    EXPECT_THROW(loadCloud(path, cloud), InputError) << bad;
  }
}

TEST(CloudReader, StudyScanWithStrayXmlLines) {
  // poli001.pcd has 6 XML lines after DATA ascii. pcl::PCDReader alone turns them into six
  // points at the origin and drops the last six real points; the reader must not.
  const std::string path = studyScan("poli001");
  Cloud cloud;
  const LoadReport r = loadCloud(path, cloud);
  EXPECT_EQ(r.skipped_lines, 6u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("6 malformed"), std::string::npos);
  ASSERT_EQ(cloud.size(), 61428u);
  // Independent parse of the text: every line with six numbers is a point, in order.
  std::istringstream body(slurp(path).substr(slurp(path).find("<data>") + 7));
  std::size_t i = 0;
  for (float x, y, z, r0, g0, b0; body >> x >> y >> z >> r0 >> g0 >> b0; ++i) {
    ASSERT_LT(i, cloud.size());
    ASSERT_EQ(cloud[i].x, x) << "point " << i;
    ASSERT_EQ(cloud[i].y, y) << "point " << i;
    ASSERT_EQ(cloud[i].z, z) << "point " << i;
  }
  EXPECT_EQ(i, 61428u);
}

TEST(CloudReader, StudyScansLoadWhole) {
  const std::pair<const char*, std::size_t> scans[] = {
      {"ciencias000", 58826}, {"museo000", 79149}, {"poli000", 62822}, {"poli001", 61428}};
  for (const auto& [name, n] : scans) {
    Cloud cloud;
    loadCloud(studyScan(name), cloud);
    EXPECT_EQ(cloud.size(), n) << name;
  }
}

TEST(CloudReader, KittiBin) {
  const std::string path = dataPath("kitti_odometry_00/sequences/00/velodyne/000000.bin");
  pcl::PointCloud<pcl::PointXYZI> cloud;
  const LoadReport r = loadCloud(path, cloud);
  const std::string raw = slurp(path);
  ASSERT_EQ(raw.size() % 16, 0u);
  ASSERT_EQ(cloud.size(), raw.size() / 16);
  EXPECT_EQ(r.format, "kitti bin");
  const float* f = reinterpret_cast<const float*>(raw.data());
  for (std::size_t i = 0; i < cloud.size(); i += 997) {
    EXPECT_EQ(cloud[i].x, f[4 * i]);
    EXPECT_EQ(cloud[i].z, f[4 * i + 2]);
    EXPECT_EQ(cloud[i].intensity, f[4 * i + 3]);
  }
}

TEST(CloudReader, PlyAsciiAndBinary) {
  TempDir tmp;
  Cloud bunny;
  loadCloud(dataPath("pcl_test_pcd/bunny.pcd"), bunny);
  for (bool binary : {false, true}) {
    const std::string path = tmp.write(binary ? "b.ply" : "a.ply", "");
    ASSERT_EQ(pcl::io::savePLYFile(path, bunny, binary), 0);
    Cloud back;
    const LoadReport r = loadCloud(path, back);
    EXPECT_EQ(r.format, "ply");
    ASSERT_EQ(back.size(), bunny.size());
    for (std::size_t i = 0; i < back.size(); ++i) {
      EXPECT_NEAR((back[i].getVector3fMap() - bunny[i].getVector3fMap()).norm(), 0.0f, 1e-6f);
    }
  }
}

TEST(CloudReader, BadInputsGiveOneLineErrors) {
  TempDir tmp;
  const std::string header =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
      "WIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\n";
  expectInputError(tmp.write("empty.pcd", ""), "empty file");
  expectInputError(tmp.write("garbage.pcd", std::string("\x89PNG\r\n\x1a\n\0\0\xff\xfe", 12)),
                   "no DATA line");
  expectInputError(tmp.write("trunc_ascii.pcd", header + "DATA ascii\n1 2 3\n4 5 6\n"),
                   "truncated ascii body: 2 of 3");
  expectInputError(tmp.write("ragged.pcd", header + "DATA ascii\n1 2 3\n4 5\n7 8 9\n"),
                   "truncated ascii body: 2 of 3");
  expectInputError(tmp.write("words.pcd", header + "DATA ascii\n1 2 3\n4 five 6\n7 8 9\n"),
                   "'five' is not a number");
  expectInputError(tmp.write("trunc_bin.pcd", header + "DATA binary\n" + std::string(20, '\0')),
                   "truncated binary body");
  std::string huge = header;
  huge.replace(huge.find("WIDTH 3"), 7, "WIDTH 4000000000");
  huge.replace(huge.find("POINTS 3"), 8, "POINTS 4000000000");
  expectInputError(tmp.write("absurd_bin.pcd", huge + "DATA binary\n" + std::string(36, '\0')),
                   "truncated binary body");
  expectInputError(tmp.write("absurd_ascii.pcd", huge + "DATA ascii\n1 2 3\n"),
                   "truncated ascii body");
  std::string mismatch = header;
  mismatch.replace(mismatch.find("HEIGHT 1"), 8, "HEIGHT 7");
  expectInputError(tmp.write("mismatch.pcd", mismatch + "DATA ascii\n1 2 3\n"),
                   "differs from POINTS");
  std::string negative = header;
  negative.replace(negative.find("WIDTH 3"), 7, "WIDTH -3");
  expectInputError(tmp.write("negative.pcd", negative + "DATA ascii\n1 2 3\n"), "WIDTH '-3'");
  expectInputError(tmp.write("nan.pcd", header + "DATA ascii\nnan nan nan\nnan 1 2\n3 nan 4\n"),
                   "no finite points");
  expectInputError(tmp.write("nofields.pcd", "VERSION 0.7\nWIDTH 1\nPOINTS 1\nDATA ascii\n1\n"),
                   "no FIELDS");
  expectInputError(dataPath("no/such/file.pcd"), "cannot open");
  expectInputError(tmp.write("cloud.xyz", "1 2 3\n"), "unknown extension");
  expectInputError(tmp.write("scan.bin", std::string(17, '\0')), "not a multiple of 16");
  expectInputError(tmp.write("bad.ply",
                             "ply\nformat ascii 1.0\nelement vertex 1000000000\n"
                             "property float x\nproperty float y\nproperty float z\n"
                             "end_header\n1 2 3\n"),
                   "announces 1000000000 vertices");
  expectInputError(tmp.write("noend.ply", "ply\nformat ascii 1.0\n"), "no end_header");

  // Corrupt compressed data: the body of milk.pcd with its middle overwritten.
  std::string milk = slurp(dataPath("pcl_test_pcd/milk.pcd"));
  const std::size_t body = milk.find("DATA binary_compressed\n") + 23;
  std::string corrupt = milk;
  for (std::size_t i = body + 8 + 100; i < body + 8 + 4000 && i < corrupt.size(); ++i)
    corrupt[i] = '\xff';
  expectInputError(tmp.write("corrupt.pcd", corrupt), "could not decode");
  expectInputError(tmp.write("cut.pcd", milk.substr(0, milk.size() / 2)),
                   "truncated binary_compressed body");
}

}  // namespace metricmap

namespace metricmap {

// Inputs the fuzzer found (scripts/fuzz): each must load or raise InputError, nothing else.
TEST(CloudReader, FuzzRegressions) {
  const fs::path dir = fs::path(METRICMAP_SOURCE_DIR) / "tests" / "fuzz_regressions";
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    Cloud cloud;
    try {
      loadCloud(entry.path().string(), cloud);
    } catch (const InputError&) {
    }
    ++files;
  }
  EXPECT_GT(files, 0u);
}

}  // namespace metricmap
