// Scan readers on the bundled real logs and on small files written here (CARMEN, bad input).
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "metricmap/exceptions.h"
#include "metricmap/io/laser_scan.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

std::string writeTemp(const std::string& name, const std::string& text) {
  const fs::path p =
      fs::temp_directory_path() / ("metricmap_scan_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

}  // namespace

TEST(LaserScan, AngleRangeCsvWithCrlf) {
  const ScanLog log =
      readAngleRangeCsv(std::string(METRICMAP_DATA_DIR) + "/pythonrobotics_lidar01/lidar01.csv");
  ASSERT_EQ(log.scans.size(), 1u);
  EXPECT_EQ(log.scans[0].ranges.size(), 154u);
  EXPECT_NEAR(log.scans[0].angles[0], 0.008450416037156572, 1e-15);
  EXPECT_NEAR(log.scans[0].ranges[0], 0.5335, 1e-12);
  EXPECT_EQ(log.scans[0].validBeams(), 154u);
}

TEST(LaserScan, MinesUrgPreset) {
  const ScanLog log = readScanLines(
      std::string(METRICMAP_DATA_DIR) + "/breezyslam_mines_urg04lx/exp2.dat", urg04lxMinesFormat());
  ASSERT_EQ(log.scans.size(), 641u);
  EXPECT_EQ(log.skipped_lines, 0u);
  const LaserScan& s = log.scans[0];
  ASSERT_EQ(s.ranges.size(), 682u);
  EXPECT_NEAR(s.angles.front(), -120.0 * M_PI / 180, 1e-12);
  EXPECT_NEAR(s.angles.back(), 120.0 * M_PI / 180, 1e-12);
  EXPECT_TRUE(std::isnan(s.ranges[0]));  // beams 0-52 read 0 (no return)
  // Token 24 + 58 of the first line is 559 (mm), as in the file's text.
  std::size_t first_valid = 0;
  while (std::isnan(s.ranges[first_valid])) ++first_valid;
  EXPECT_NEAR(s.ranges[first_valid], 0.559, 1e-12);
  for (const LaserScan& scan : log.scans) {
    for (double r : scan.ranges) EXPECT_TRUE(std::isnan(r) || r >= 0.02);
  }
}

TEST(LaserScan, CarmenFlaserAndRobotLaser) {
  const std::string path = writeTemp(
      "log.carmen",
      "# CARMEN Logfile\nODOM 0 0 0 0 0 0 1.0 host 1.0\n"
      "FLASER 181 " +
          [] {
            std::string r;
            for (int i = 0; i < 181; ++i) r += "2.5 ";
            return r;
          }() +
          "0 0 0 0 0 0 1.0 host 1.0\n"
          "ROBOTLASER1 0 -1.5708 3.14159 0.0174533 81.9 0.01 0 3 1.0 81.9 2.0 0 0 0 0 0 0 0 0 0 0 "
          "0 0 1.0 host 1.0\n"
          "FLASER 3 1.0 oops 1.0 0 0 0 0 0 0 1.0 host 1.0\n");
  const ScanLog log = readCarmenLog(path);
  ASSERT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.skipped_lines, 1u);
  EXPECT_EQ(log.warnings.size(), 1u);
  EXPECT_EQ(log.scans[0].ranges.size(), 181u);
  EXPECT_NEAR(log.scans[0].angles[0], -M_PI / 2, 1e-12);
  EXPECT_NEAR(log.scans[0].angles[180], M_PI / 2, 1e-12);  // 181 beams: 1 degree, both ends
  ASSERT_EQ(log.scans[1].ranges.size(), 3u);
  EXPECT_NEAR(log.scans[1].angles[1], -1.5708 + 0.0174533, 1e-12);
  EXPECT_TRUE(std::isnan(log.scans[1].ranges[1]));  // 81.9 = maximum range: no return
  EXPECT_DOUBLE_EQ(log.scans[1].ranges[2], 2.0);
  EXPECT_TRUE(looksLikeCarmen(path));
  fs::remove(path);
}

TEST(LaserScan, BadInput) {
  const std::string bad_csv = writeTemp("bad.csv", "0.1,1.0\r\n0.2,abc\r\n");
  EXPECT_THROW(readAngleRangeCsv(bad_csv), InputError);
  const std::string empty = writeTemp("empty.csv", "");
  EXPECT_THROW(readAngleRangeCsv(empty), InputError);
  ScanLineFormat f;
  f.count = 3;
  const std::string lines = writeTemp("lines.dat", "1 2 3\n1 2\nx y z\n4 5 6\n");
  const ScanLog log = readScanLines(lines, f);
  EXPECT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.skipped_lines, 2u);
  const std::string none = writeTemp("none.dat", "1 2\n");
  EXPECT_THROW(readScanLines(none, f), InputError);
  EXPECT_THROW(readScanLines("/no/such/file", f), InputError);
  f.count = 0;
  EXPECT_THROW(readScanLines(lines, f), std::invalid_argument);
  for (const auto& p : {bad_csv, empty, lines, none}) fs::remove(p);
}

}  // namespace metricmap
