// CARMEN logs as a scan source, on the real Radish logs (../shared/data/radish_clf_raw): counts,
// ranges, stamps and odometry against an independent parse (bzcat through popen, each line split
// with std::istringstream here) and the figures of SOURCE.md; gzip and plain copies made with
// gzip/bzcat; damaged streams, long lines and decompression bombs refused naming the file.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/datasets/carmen_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/carmen_log.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/text_stream.h"
#include "scratch_files.h"
#include "shared_data.h"
#include "temp_dir.h"

namespace metricmap {
namespace {

std::string radish(const std::string& name) {
  return std::string(METRICMAP_SHARED_DATA_DIR) + "/radish_clf_raw/" + name;
}

#define REQUIRE_FILE(path) SKIP_WITHOUT_SHARED_DATA(path)

/// One FLASER line as the oracle reads it.
struct OracleScan {
  std::size_t line = 0;
  std::vector<double> ranges;
  double odom[3] = {0, 0, 0};
  double stamp = 0;
};

struct OracleLog {
  std::vector<OracleScan> scans;
  std::size_t odom_lines = 0;
};

/// The log's text from a command (bzcat, cat), FLASER lines split with std::istringstream.
OracleLog oracle(const std::string& command) {
  OracleLog log;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
  if (!pipe) return log;
  std::string line;
  std::size_t number = 0;
  char buf[1 << 16];
  auto one = [&](const std::string& text) {
    ++number;
    std::istringstream is(text);
    std::string kind;
    is >> kind;
    if (kind == "ODOM") ++log.odom_lines;
    if (kind != "FLASER") return;
    OracleScan s;
    s.line = number;
    std::size_t n = 0;
    is >> n;
    s.ranges.resize(n);
    for (double& r : s.ranges) is >> r;
    double laser[3];
    std::string host;
    is >> laser[0] >> laser[1] >> laser[2] >> s.odom[0] >> s.odom[1] >> s.odom[2] >> s.stamp;
    if (is) log.scans.push_back(std::move(s));
  };
  while (std::fgets(buf, sizeof buf, pipe.get())) {
    line += buf;
    if (!line.empty() && line.back() == '\n') {
      one(line);
      line.clear();
    }
  }
  if (!line.empty()) one(line);
  return log;
}

/// Scan i of the source against the oracle's: every range, the stamp, the odometry, the name.
void expectSame(const std::string& path, const Scan& scan, const OracleScan& o) {
  ASSERT_TRUE(scan.laser.has_value());
  ASSERT_EQ(scan.laser->ranges.size(), o.ranges.size());
  ASSERT_EQ(scan.points.size(), o.ranges.size());
  const double step =
      M_PI / static_cast<double>(o.ranges.size() % 2 ? o.ranges.size() - 1 : o.ranges.size());
  for (std::size_t k = 0; k < o.ranges.size(); ++k) {
    const double a = -M_PI / 2 + step * static_cast<double>(k);
    EXPECT_NEAR(scan.laser->angles[k], a, 1e-12);
    if (o.ranges[k] > 0) {
      EXPECT_DOUBLE_EQ(scan.laser->ranges[k], o.ranges[k]) << k;
      EXPECT_NEAR(scan.points[k].x, o.ranges[k] * std::cos(a), 1e-4);
      EXPECT_NEAR(scan.points[k].y, o.ranges[k] * std::sin(a), 1e-4);
      EXPECT_EQ(scan.points[k].z, 0.0f);
    } else {
      EXPECT_TRUE(std::isnan(scan.laser->ranges[k]));
      EXPECT_TRUE(std::isnan(scan.points[k].x));
    }
  }
  EXPECT_DOUBLE_EQ(scan.stamp, o.stamp);
  ASSERT_TRUE(scan.odometry.has_value());
  EXPECT_NEAR(scan.odometry->translation().x(), o.odom[0], 1e-12);
  EXPECT_NEAR(scan.odometry->translation().y(), o.odom[1], 1e-12);
  EXPECT_NEAR(scan.odometry->translation().z(), 0.0, 1e-12);
  const Eigen::Vector3d heading = scan.odometry->linear() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(heading.x(), std::cos(o.odom[2]), 1e-12);
  EXPECT_NEAR(heading.y(), std::sin(o.odom[2]), 1e-12);
  EXPECT_EQ(scan.name, path + ": line " + std::to_string(o.line));
}

struct RealLog {
  const char* file;
  std::size_t flaser;  // SOURCE.md
  std::size_t ranges;  // SOURCE.md
  std::size_t odom;    // SOURCE.md
};

class CarmenRealLog : public ::testing::TestWithParam<RealLog> {};

TEST_P(CarmenRealLog, MatchesAnIndependentParseAndSourceMd) {
  const RealLog& p = GetParam();
  const std::string path = radish(p.file);
  REQUIRE_FILE(path);
  const OracleLog o = oracle("bzcat '" + path + "'");
  ASSERT_EQ(o.scans.size(), p.flaser);
  EXPECT_EQ(o.odom_lines, p.odom);

  CarmenSource source(path);
  EXPECT_EQ(source.size(), p.flaser);
  EXPECT_EQ(source.odometryLines(), p.odom);
  EXPECT_EQ(source.skippedLines(), 0u);
  EXPECT_TRUE(source.warnings().empty());
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.kind, "carmen");
  EXPECT_EQ(info.path, path);
  EXPECT_TRUE(info.planar);
  EXPECT_FALSE(info.point_times);
  EXPECT_TRUE(info.sensor_to_base.isApprox(Eigen::Isometry3d::Identity()));
  ASSERT_EQ(info.stamps.size(), o.scans.size());
  std::size_t steps_back = 0;
  for (std::size_t i = 0; i < o.scans.size(); ++i) {
    ASSERT_DOUBLE_EQ(info.stamps[i], o.scans[i].stamp) << i;
    steps_back += i > 0 && o.scans[i].stamp < o.scans[i - 1].stamp;
  }
  std::cout << p.file << ": " << source.size() << " scans, " << source.odometryLines()
            << " ODOM lines, stamps " << std::fixed << info.stamps.front() << " .. "
            << info.stamps.back() << ", " << steps_back << " steps back\n";

  // Forward through a few scans, then back: the source reads the log again.
  const std::size_t n = source.size();
  for (std::size_t i : {std::size_t{0}, std::size_t{1}, std::size_t{2}, n / 3, n / 2, n - 1}) {
    SCOPED_TRACE(i);
    const Scan s = source.scan(i);
    EXPECT_EQ(s.index, i);
    EXPECT_EQ(s.laser->ranges.size(), p.ranges);
    expectSame(path, s, o.scans[i]);
  }
  for (std::size_t i : {std::size_t{7}, n / 2, std::size_t{0}}) {
    SCOPED_TRACE(i);
    expectSame(path, source.scan(i), o.scans[i]);
  }
  EXPECT_THROW(source.scan(n), metricmap::InputError);

  // The ScanLog reader goes through the same parser (the smallest log only: it reads it whole).
  if (p.flaser > 2000) return;
  const ScanLog log = readScanLog(path);
  ASSERT_EQ(log.scans.size(), p.flaser);
  EXPECT_EQ(log.scans[n / 3].ranges, source.scan(n / 3).laser->ranges);
  EXPECT_EQ(detectScanLog(path), ScanLogKind::Carmen);
}

INSTANTIATE_TEST_SUITE_P(Radish, CarmenRealLog,
                         ::testing::Values(RealLog{"intel.clf.bz2", 13631, 180, 26915},
                                           RealLog{"fr079.clf.bz2", 4934, 360, 8951},
                                           RealLog{"mit-csail.clf.bz2", 1988, 361, 0}),
                         [](const ::testing::TestParamInfo<RealLog>& i) {
                           std::string n = i.param.file;
                           return n.substr(0, n.find_first_of("-.")) +
                                  (n.find('-') != std::string::npos ? "Csail" : "");
                         });

TEST(CarmenSource, GzipAndPlainCopiesReadTheSame) {
  const std::string bz2 = radish("mit-csail.clf.bz2");
  REQUIRE_FILE(bz2);
  TempDir dir("carmen_copies");
  // Named without a telling extension: the compression comes from the first bytes.
  const std::string gz = dir / "mit.log", gz_named = dir / "mit.clf.gz", plain = dir / "mit.clf";
  ASSERT_EQ(std::system(("bzcat '" + bz2 + "' | gzip -c > '" + gz + "'").c_str()), 0);
  ASSERT_EQ(std::system(("cp '" + gz + "' '" + gz_named + "'").c_str()), 0);
  ASSERT_EQ(std::system(("bzcat '" + bz2 + "' > '" + plain + "'").c_str()), 0);
  EXPECT_EQ(detectCompression(gz), TextCompression::Gzip);
  EXPECT_EQ(detectCompression(bz2), TextCompression::Bzip2);
  EXPECT_EQ(detectCompression(plain), TextCompression::None);

  const OracleLog o = oracle("cat '" + plain + "'");
  CarmenSource reference(bz2);
  for (const std::string& path : {gz, gz_named, plain}) {
    SCOPED_TRACE(path);
    CarmenSource source(path);
    ASSERT_EQ(source.size(), reference.size());
    EXPECT_EQ(source.info().stamps, reference.info().stamps);
    for (std::size_t i : {std::size_t{5}, std::size_t{1000}, std::size_t{3}}) {
      expectSame(path, source.scan(i), o.scans[i]);
    }
    EXPECT_EQ(detectScanLog(path), ScanLogKind::Carmen);
    EXPECT_EQ(readCarmenLog(path).scans.size(), o.scans.size());
  }
  // Other scan logs take compressed files too: a gzipped CSV.
  const std::string csv = dir / "lidar01.csv.gz";
  ASSERT_EQ(std::system(("gzip -c '" + std::string(METRICMAP_DATA_DIR) +
                         "/pythonrobotics_lidar01/lidar01.csv' > '" + csv + "'")
                            .c_str()),
            0);
  EXPECT_EQ(detectScanLog(csv), ScanLogKind::AngleRangeCsv);
  EXPECT_EQ(readScanLog(csv).scans.at(0).ranges.size(), 154u);
}

using test_support::inputErrorOf;

TEST(CarmenSource, DamagedStreamsNameTheFile) {
  const std::string bz2 = radish("mit-csail.clf.bz2");
  REQUIRE_FILE(bz2);
  TempDir dir("carmen_damaged");
  const std::string cut = dir / "cut.clf.bz2", gz = dir / "ok.clf.gz", bad = dir / "bad.clf.gz";
  const auto size = std::filesystem::file_size(bz2);
  ASSERT_EQ(std::system(
                ("head -c " + std::to_string(size / 2) + " '" + bz2 + "' > '" + cut + "'").c_str()),
            0);
  ASSERT_EQ(std::system(("bzcat '" + bz2 + "' | gzip -c > '" + gz + "'").c_str()), 0);
  {  // one byte flipped in the middle of the deflate data
    std::ifstream in(gz, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
    std::ofstream(bad, std::ios::binary) << bytes;
  }
  // The cut stream ends early; the flipped byte shows at the latest in the CRC (zlib may first
  // inflate it to garbage, which can also be refused as an overlong line).
  for (const std::string& path : {cut, bad}) {
    SCOPED_TRACE(path);
    for (const std::string& m :
         {inputErrorOf([&] { CarmenSource s(path); }), inputErrorOf([&] { readScanLog(path); })}) {
      EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
      if (path == cut) {
        EXPECT_NE(m.find("corrupt or truncated bzip2 stream"), std::string::npos) << m;
      }
    }
  }
  // A stream cut inside its first bytes, and an empty file.
  const std::string stub = dir / "stub.bz2";
  std::ofstream(stub, std::ios::binary) << "BZh9";
  EXPECT_NE(inputErrorOf([&] { CarmenSource s(stub); }).find(stub), std::string::npos);
  const std::string empty = dir / "empty.clf";
  std::ofstream(empty, std::ios::binary).flush();
  EXPECT_NE(inputErrorOf([&] { CarmenSource s(empty); }).find(empty + ": no FLASER"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { CarmenSource s(dir / "missing.clf"); }).find("missing.clf"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { CarmenSource s(dir.path.string()); }).find("a directory"),
            std::string::npos);
}

TEST(CarmenSource, LongLinesAndBombsAreRefused) {
  TempDir dir("carmen_bounds");
  // A line over 1 MiB: refused with its number, before it is held whole.
  const std::string longline =
      dir.write("long.clf", "FLASER 1 1.0\nFLASER 2 " + std::string(std::size_t{3} << 20, '1'));
  const std::string m = inputErrorOf([&] { CarmenSource s(longline); });
  EXPECT_NE(m.find(longline + ": line 2: longer than 1048576 bytes"), std::string::npos) << m;
  // 16 MiB of newlines compress to a few hundred bytes: past the expansion limit the reader
  // stops (here with a 1 MiB floor; the default floor is 256 MiB).
  const std::string bomb = dir / "bomb.bz2";
  ASSERT_EQ(
      std::system(
          ("head -c 16777216 /dev/zero | tr '\\0' '\\n' | bzip2 -c > '" + bomb + "'").c_str()),
      0);
  EXPECT_LT(std::filesystem::file_size(bomb), 4096u);
  TextLimits limits;
  limits.min_expanded_bytes = 1 << 20;
  TextLineReader reader(bomb, limits);
  std::string line;
  const std::string b = inputErrorOf([&] {
    while (reader.next(line)) {
    }
  });
  EXPECT_NE(b.find(bomb + ": expands to more than 1048576 bytes"), std::string::npos) << b;
  EXPECT_LE(reader.textBytes(), (1u << 20) + (1u << 16));
}

TEST(CarmenLog, StampsOdometryAndOldForms) {
  TempDir dir("carmen_forms");
  const std::string path =
      dir.write("forms.clf",
                "# CARMEN Logfile\r\n"
                "ODOM 1 2 0.5 0 0 0 10.5 host 0.1\n"
                "FLASER 3 1.0 2.0 0 5 6 0.25 7 8 0.75 12.25 host 0.2\n"
                "FLASER 3 1.0 2.0 3.0\n"                         // oldest: ranges only
                "FLASER 3 1.0 2.0 3.0 1 2 3 4 5 6\n"             // poses, no stamp
                "FLASER 3 1.0 2.0 3.0 1 2\n"                     // cut inside the poses: malformed
                "FLASER 3 1.0 2.0 3.0 1 2 3 4 5 nan 1 host 1\n"  // bad odometry: malformed
                "ROBOTLASER1 0 -1.5 3.0 0.5 80 0.01 0 3 1.5 80 2.5 2 9 9 "
                "0.1 0.2 0.3 1.1 1.2 1.3 0 0 0 0 0 13.5 host 0.3\r\n");
  CarmenLogReader reader(path);
  CarmenLaser m;
  ASSERT_TRUE(reader.next(m));
  EXPECT_EQ(m.line, 3u);
  EXPECT_FALSE(m.robot_laser);
  EXPECT_EQ(m.scan.ranges.size(), 3u);
  EXPECT_TRUE(std::isnan(m.scan.ranges[2]));  // 0: no return
  EXPECT_DOUBLE_EQ(m.stamp, 12.25);
  ASSERT_TRUE(m.odometry && m.laser_pose);
  EXPECT_DOUBLE_EQ(m.laser_pose->theta, 0.25);
  EXPECT_DOUBLE_EQ(m.odometry->x, 7);
  EXPECT_DOUBLE_EQ(m.odometry->theta, 0.75);
  ASSERT_TRUE(reader.next(m));
  EXPECT_EQ(m.line, 4u);
  EXPECT_TRUE(std::isnan(m.stamp));
  EXPECT_FALSE(m.odometry.has_value());
  ASSERT_TRUE(reader.next(m));
  EXPECT_EQ(m.line, 5u);
  EXPECT_TRUE(std::isnan(m.stamp));
  ASSERT_TRUE(m.odometry.has_value());
  EXPECT_DOUBLE_EQ(m.odometry->theta, 6);
  ASSERT_TRUE(reader.next(m));
  EXPECT_EQ(m.line, 8u);
  EXPECT_TRUE(m.robot_laser);
  EXPECT_DOUBLE_EQ(m.scan.angles[2], -1.5 + 2 * 0.5);
  EXPECT_TRUE(std::isnan(m.scan.ranges[1]));  // the maximum range: no return
  EXPECT_DOUBLE_EQ(m.stamp, 13.5);
  EXPECT_DOUBLE_EQ(m.laser_pose->x, 0.1);
  EXPECT_DOUBLE_EQ(m.odometry->theta, 1.3);
  EXPECT_FALSE(reader.next(m));
  EXPECT_EQ(reader.skippedLines(), 2u);
  EXPECT_EQ(reader.odometryLines(), 1u);

  // As a source: scans without stamps make the source's stamps unknown, with a warning.
  CarmenSource source(path);
  EXPECT_EQ(source.size(), 4u);
  EXPECT_TRUE(source.info().stamps.empty());
  EXPECT_EQ(source.warnings().size(), 2u);
  EXPECT_EQ(source.scan(3).name, path + ": line 8");
  EXPECT_FALSE(source.scan(1).odometry.has_value());
  EXPECT_DOUBLE_EQ(source.scan(0).stamp, 12.25);

  // Only ROBOTLASER1 lines: the laser's offset on the robot is the sensor -> base extrinsic.
  const std::string robot = dir.write("robot.clf",
                                      "ROBOTLASER1 0 -1.5 3.0 0.5 80 0.01 0 3 1.5 80 2.5 0 "
                                      "1.1 2 1.5707963267948966 1 2 1.5707963267948966 "
                                      "0 0 0 0 0 13.5 host 0.3\n");
  CarmenSource r(robot);
  const Eigen::Vector3d offset = r.info().sensor_to_base.translation();
  EXPECT_NEAR(offset.x(), 0.0, 1e-12);  // 0.1 m along the world x = the robot's -y
  EXPECT_NEAR(offset.y(), -0.1, 1e-12);
  ASSERT_EQ(r.info().stamps.size(), 1u);
}

}  // namespace
}  // namespace metricmap
