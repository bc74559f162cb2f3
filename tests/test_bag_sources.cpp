// ROS bags as scan sources: every fixture of tests/fixtures/bags/ (written by
// independent writers: @mcap/core, @foxglove/rosmsg2-serialization, Python's sqlite3; see
// tools/fixtures/) read back equal, point for point and time for time, to the scans it was made
// from, read here with the project's other readers (KITTI source, readScanFile, CARMEN source);
// odometry and a map from the KITTI-frames bag equal those from the KITTI layout; topic
// selection; the real nebula VLP-16 rosbag2 bag; hostile containers and messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include <sqlite3.h>

#include "metricmap/datasets/bag_source.h"
#include "metricmap/datasets/carmen_source.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/bag_reader.h"
#include "metricmap/io/point_cloud2.h"
#include "metricmap/io/scan_file.h"
#include "metricmap/sequence/odometry_run.h"
#include "metricmap/sequence/sequence_mapper.h"
#include "shared_data.h"
#include "temp_dir.h"

namespace {

namespace fs = std::filesystem;
using metricmap::InputError;

const std::string kData = METRICMAP_DATA_DIR;
const std::string kBags = std::string(METRICMAP_SOURCE_DIR) + "/tests/fixtures/bags";
const std::string kShared = METRICMAP_SHARED_DATA_DIR;
const std::vector<std::string> kMixed = {
    "mixed.db3",          "mixed_lz4.mcap",    "mixed_zstd_nosummary.mcap", "mixed_unchunked.mcap",
    "mixed_ros1_bz2.bag", "mixed_ros1_lz4.bag"};

metricmap::ScanSourceOptions topic(const std::string& t) {
  metricmap::ScanSourceOptions o;
  o.topic = t;
  return o;
}

bool same(float a, float b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

std::vector<std::uint8_t> readAll(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}
void writeAll(const std::string& p, const std::vector<std::uint8_t>& b) {
  std::ofstream(p, std::ios::binary)
      .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

// Every scan of every scan topic of a bag: what a command reading it would do.
void readEverything(const std::string& path) {
  auto bag = metricmap::openBag(path);
  for (const metricmap::BagTopic& t : bag->topics()) {
    if (metricmap::bagScanType(t.type) == metricmap::BagScanType::None) continue;
    metricmap::BagSource s(path, topic(t.name));
    for (std::size_t i = 0; i < s.size(); ++i) (void)s.scan(i);
  }
}

TEST(BagSource, KittiFramesEqualTheKittiLayout) {
  auto kitti = metricmap::openScanSource(kData + "/kitti_odometry_00");
  metricmap::BagSource bag(kBags + "/kitti3_zstd.mcap", {});
  EXPECT_EQ(bag.info().kind, "bag");
  EXPECT_EQ(bag.topic().name, "/kitti/velodyne");
  ASSERT_EQ(bag.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const metricmap::Scan a = kitti->scan(i), b = bag.scan(i);
    const metricmap::ScanFile f = metricmap::readScanFile(
        kData + "/kitti_odometry_00/sequences/00/velodyne/00000" + std::to_string(i) + ".bin");
    ASSERT_EQ(a.points.size(), b.points.size());
    ASSERT_EQ(f.points.size(), b.points.size());
    ASSERT_EQ(f.intensity.size(), b.intensity.size());
    for (std::size_t k = 0; k < b.points.size(); ++k) {
      ASSERT_EQ(a.points[k].x, b.points[k].x);
      ASSERT_EQ(a.points[k].y, b.points[k].y);
      ASSERT_EQ(a.points[k].z, b.points[k].z);
      ASSERT_EQ(f.intensity[k], b.intensity[k]);
    }
    EXPECT_TRUE(b.point_times.empty());
    EXPECT_NEAR(a.stamp, b.stamp, 1e-9);
  }
}

TEST(BagSource, OdometryAndMapFromKittiBagEqualTheKittiLayout) {
  auto kitti = metricmap::openScanSource(kData + "/kitti_odometry_00");
  metricmap::BagSource bag(kBags + "/kitti3_zstd.mcap", {});
  metricmap::OdometryRunOptions o;
  o.frames = {0, 1, 2};
  const metricmap::OdometryRun a = metricmap::runOdometry(*kitti, o);
  const metricmap::OdometryRun b = metricmap::runOdometry(bag, o);
  ASSERT_EQ(a.frames.size(), 3u);
  ASSERT_EQ(b.frames.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_TRUE(a.frames[k].result.pose.matrix() == b.frames[k].result.pose.matrix()) << k;
    EXPECT_EQ(a.frames[k].result.points_used, b.frames[k].result.points_used);
  }
  EXPECT_GT(b.frames[2].result.pose.translation().norm(), 0.5);  // the car moved
  // A map from the same sensor poses.
  metricmap::ScanMapperConfig c;
  c.voxel = 0.5;
  c.up = Eigen::Vector3f(0, 0, 1);
  c.plane = metricmap::MapPlane::XY;
  c.map_resolution = 0.5;
  std::vector<Eigen::Isometry3d> poses;
  for (const auto& f : a.frames) poses.push_back(f.result.pose);
  metricmap::SequenceMapper ma(*kitti, c), mb(bag, c);
  const metricmap::ScanMapper& sa = ma.build(poses, o.frames);
  const metricmap::ScanMapper& sb = mb.build(poses, o.frames);
  EXPECT_EQ(sa.map().image().hits, sb.map().image().hits);
  const auto ca = sa.globalCloud();
  const auto cb = sb.globalCloud();
  ASSERT_GT(ca.size(), 1000u);
  ASSERT_EQ(ca.size(), cb.size());
  for (std::size_t k = 0; k < ca.size(); ++k) {
    ASSERT_EQ(ca[k].x, cb[k].x);
    ASSERT_EQ(ca[k].y, cb[k].y);
    ASSERT_EQ(ca[k].z, cb[k].z);
  }
}

class MixedBag : public ::testing::TestWithParam<std::string> {
 protected:
  std::string path() const { return kBags + "/" + GetParam(); }
};

TEST_P(MixedBag, Vlp16CloudEqualsThePcdWithItsTimes) {
  metricmap::BagSource bag(path(), topic("/velodyne_points"));
  ASSERT_EQ(bag.size(), 1u);
  EXPECT_TRUE(bag.info().point_times);
  EXPECT_FALSE(bag.info().planar);
  const metricmap::ScanFile f =
      metricmap::readScanFile(kData + "/nebula_vlp16/vlp16_1673400472138016708.pcd");
  const metricmap::Scan s = bag.scan(0);
  ASSERT_EQ(f.points.size(), 14831u);
  ASSERT_EQ(s.points.size(), f.points.size());
  ASSERT_EQ(s.intensity.size(), f.intensity.size());
  ASSERT_EQ(s.point_times.size(), f.point_times.size());
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    ASSERT_EQ(s.points[k].x, f.points[k].x);
    ASSERT_EQ(s.points[k].y, f.points[k].y);
    ASSERT_EQ(s.points[k].z, f.points[k].z);
    ASSERT_EQ(s.intensity[k], f.intensity[k]);
    ASSERT_EQ(s.point_times[k], f.point_times[k]);
  }
  EXPECT_NEAR(s.stamp, 1673400472.138016708, 1e-6);
}

TEST_P(MixedBag, OrganisedBigEndianFloat64CloudEqualsItsKittiPoints) {
  metricmap::BagSource bag(path(), topic("/odd_cloud"));
  const metricmap::Scan s = bag.scan(0);
  const metricmap::ScanFile f =
      metricmap::readScanFile(kData + "/kitti_odometry_00/sequences/00/velodyne/000001.bin");
  // 64 x 64 points, every 97th NaN (dropped); t = 1000 ns per point, from the earliest kept.
  std::size_t j = 0;
  const double lo = 1000.0 * 1e-9;
  for (std::size_t k = 0; k < 4096; ++k) {
    if (k % 97 == 0) continue;
    ASSERT_LT(j, s.points.size());
    ASSERT_EQ(s.points[j].x, f.points[k].x);
    ASSERT_EQ(s.points[j].y, f.points[k].y);
    ASSERT_EQ(s.points[j].z, f.points[k].z);
    ASSERT_EQ(s.intensity[j], f.intensity[k]);
    ASSERT_EQ(s.point_times[j], 1000.0 * static_cast<double>(k) * 1e-9 - lo);
    ++j;
  }
  EXPECT_EQ(j, s.points.size());
}

TEST_P(MixedBag, LaserScansEqualTheCarmenLog) {
  const std::string log = kData + "/radish_clf_raw/intel.clf.bz2";
  metricmap::BagSource bag(path(), topic("/scan"));
  EXPECT_TRUE(bag.info().planar);
  ASSERT_EQ(bag.size(), 40u);
  metricmap::CarmenSource carmen(log);
  for (std::size_t i = 0; i < 40; ++i) {
    const metricmap::Scan a = carmen.scan(i), b = bag.scan(i);
    ASSERT_TRUE(a.laser && b.laser);
    ASSERT_EQ(a.laser->ranges.size(), b.laser->ranges.size());
    for (std::size_t k = 0; k < a.laser->ranges.size(); ++k) {
      ASSERT_TRUE(
          same(static_cast<float>(a.laser->ranges[k]), static_cast<float>(b.laser->ranges[k])))
          << i << " " << k;
      ASSERT_NEAR(a.laser->angles[k], b.laser->angles[k], 1e-6);  // float32 angle_min, step
    }
    ASSERT_EQ(a.points.size(), b.points.size());
    EXPECT_NEAR(a.stamp, b.stamp, 1e-6);
  }
}

TEST_P(MixedBag, TopicsCountsAndSelection) {
  auto bag = metricmap::openBag(path());
  std::map<std::string, std::pair<std::string, std::uint64_t>> t;
  for (const auto& x : bag->topics()) t[x.name] = {x.type, x.messages};
  ASSERT_EQ(t.size(), 4u);
  const bool ros1 = bag->format() == "rosbag1";
  EXPECT_EQ(t["/scan"].first, ros1 ? "sensor_msgs/LaserScan" : "sensor_msgs/msg/LaserScan");
  EXPECT_EQ(t["/scan"].second, 40u);
  EXPECT_EQ(t["/velodyne_points"].second, 1u);
  EXPECT_EQ(t["/odd_cloud"].second, 1u);
  EXPECT_EQ(t["/chatter"].first, ros1 ? "std_msgs/String" : "std_msgs/msg/String");
  for (const auto& x : bag->topics()) {
    if (x.name != "/scan") continue;
    EXPECT_EQ(x.first_ns, 1673400472000000000);
    EXPECT_EQ(x.last_ns, 1673400472000000000 + 39 * 100000000LL);
  }
  // Three scan topics: no default.
  try {
    metricmap::BagSource s(path(), {});
    FAIL();
  } catch (const metricmap::TopicSelectionError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--topic"), std::string::npos) << m;
    EXPECT_NE(m.find("/odd_cloud"), std::string::npos) << m;
    EXPECT_EQ(m.find("/chatter"), std::string::npos) << m;
  }
  // slam2d takes the only LaserScan topic, odometry has two PointCloud2 topics to choose from.
  metricmap::ScanSourceOptions laser;
  laser.bag_scans = "laser";
  EXPECT_EQ(metricmap::BagSource(path(), laser).topic().name, "/scan");
  metricmap::ScanSourceOptions cloud;
  cloud.bag_scans = "cloud";
  try {
    metricmap::BagSource s(path(), cloud);
    FAIL();
  } catch (const metricmap::TopicSelectionError& e) {
    EXPECT_NE(std::string(e.what()).find("2 sensor_msgs/msg/PointCloud2 topics"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(metricmap::BagSource(path(), topic("/chatter")), metricmap::TopicSelectionError);
  EXPECT_THROW(metricmap::BagSource(path(), topic("/nope")), metricmap::TopicSelectionError);
  EXPECT_EQ(metricmap::scanSourceKind(path(), "auto"), "bag");
}

INSTANTIATE_TEST_SUITE_P(Fixtures, MixedBag, ::testing::ValuesIn(kMixed));

TEST(BagSource, RealNebulaVlp16BagListsPacketsAndRefusesThem) {
  const std::string dir = kShared + "/nebula_driver_samples/vlp16_bag";
  SKIP_WITHOUT_SHARED_DATA(dir);
  for (const std::string& p : {dir, dir + "/1673400471837873222_0.db3"}) {
    auto bag = metricmap::openBag(p);
    EXPECT_EQ(bag->format(), "rosbag2-sqlite3");
    ASSERT_EQ(bag->topics().size(), 1u);
    EXPECT_EQ(bag->topics()[0].name, "/velodyne_packets");
    EXPECT_EQ(bag->topics()[0].type, "velodyne_msgs/msg/VelodyneScan");
    EXPECT_EQ(bag->topics()[0].messages, 4u);
    EXPECT_EQ(bag->topics()[0].first_ns, 1673400471837873222);
    EXPECT_EQ(bag->topics()[0].last_ns - bag->topics()[0].first_ns, 300143486);
    try {
      metricmap::BagSource s(p, {});
      FAIL();
    } catch (const metricmap::TopicSelectionError& e) {
      EXPECT_NE(std::string(e.what()).find("velodyne_msgs/msg/VelodyneScan"), std::string::npos);
    }
  }
}

// --- hostile containers ------------------------------------------------------------------

// The first chunk record of an MCAP file: its offset (after the magic and the Header record).
std::size_t firstChunk(const std::vector<std::uint8_t>& b) {
  std::size_t at = 8;
  while (at + 9 <= b.size() && b[at] != 0x06) {
    std::uint64_t len = 0;
    for (int k = 8; k >= 1; --k) len = (len << 8) | b[at + k];
    at += 9 + len;
  }
  return at;
}

void expectInputError(const std::string& path, const std::string& needle) {
  try {
    readEverything(path);
    ADD_FAILURE() << path << ": no error";
  } catch (const std::runtime_error& e) {  // InputError, or CapacityError for a huge size
    const std::string m = e.what();
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find(needle), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(BagHostile, McapWrongMagicGarbageAndTruncation) {
  TempDir dir("bag_hostile");
  const auto good = readAll(kBags + "/mixed_lz4.mcap");
  auto b = good;
  b[1] = 'X';
  writeAll(dir / "magic.mcap", b);
  expectInputError(dir / "magic.mcap", "not a bag");
  std::mt19937 rng(7);
  std::vector<std::uint8_t> garbage(5000);
  for (auto& c : garbage) c = static_cast<std::uint8_t>(rng());
  writeAll(dir / "garbage.mcap", garbage);
  expectInputError(dir / "garbage.mcap", "not a bag");
  // Truncated anywhere: an error naming the file, or (only the end magic or footer cut) the
  // scans read by the linear scan; never a crash.
  for (std::size_t cut : {std::size_t(9), std::size_t(30), good.size() / 3, good.size() / 2,
                          good.size() - 100, good.size() - 30, good.size() - 8, good.size() - 1}) {
    writeAll(dir / "cut.mcap", std::vector<std::uint8_t>(good.begin(), good.begin() + cut));
    try {
      readEverything(dir / "cut.mcap");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(dir / "cut.mcap"), std::string::npos);
    }
  }
  writeAll(dir / "half.mcap",
           std::vector<std::uint8_t>(good.begin(), good.begin() + good.size() / 2));
  expectInputError(dir / "half.mcap", "truncated");
}

TEST(BagHostile, FuzzRegressions) {
  // An empty uncompressed chunk (fuzz_bags: memcpy from a null buffer, UBSan).
  const std::string p =
      std::string(METRICMAP_SOURCE_DIR) + "/tests/fuzz_regressions/bag_mcap_empty_chunk.mcap";
  try {
    readEverything(p);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
  }
}

TEST(BagHostile, McapDamagedChunks) {
  TempDir dir("bag_chunks");
  for (const char* name : {"mixed_lz4.mcap", "mixed_zstd_nosummary.mcap"}) {
    const auto good = readAll(kBags + "/" + name);
    const std::size_t c = firstChunk(good);
    ASSERT_LT(c + 60, good.size());
    // Content: start u64, end u64, uncompressed size u64 (+9+16), crc u32 (+9+24),
    // compression string (+9+28: length, then its bytes), compressed size u64, records.
    const std::size_t usize = c + 9 + 16, crc = c + 9 + 24, comp = c + 9 + 28;
    const std::uint32_t clen = good[comp];
    const std::size_t csize = comp + 4 + clen, records = csize + 8;
    auto b = good;
    b[crc] ^= 0x55;
    writeAll(dir / "crc.mcap", b);
    expectInputError(dir / "crc.mcap", "CRC");
    b = good;
    b[records + 40] ^= 0xFF;
    b[records + 41] ^= 0xFF;
    writeAll(dir / "data.mcap", b);
    expectInputError(dir / "data.mcap", "byte " + std::to_string(c));
    b = good;
    b[csize] ^= 0x01;
    writeAll(dir / "csize.mcap", b);
    expectInputError(dir / "csize.mcap", "compressed bytes");
    b = good;
    b[usize + 7] = 0x10;  // 2^60 bytes
    writeAll(dir / "usize.mcap", b);
    expectInputError(dir / "usize.mcap", "byte " + std::to_string(c));
    b = good;
    b[comp + 4] = 'q';
    writeAll(dir / "comp.mcap", b);
    expectInputError(dir / "comp.mcap", "unknown chunk compression");
    b = good;
    for (int k = 1; k <= 8; ++k) b[c + k] = 0xFF;  // the chunk record's length
    writeAll(dir / "len.mcap", b);
    expectInputError(dir / "len.mcap", "truncated");
  }
}

TEST(BagHostile, Sqlite) {
  TempDir dir("bag_sqlite");
  const auto good = readAll(kBags + "/mixed.db3");
  writeAll(dir / "half.db3",
           std::vector<std::uint8_t>(good.begin(), good.begin() + good.size() / 2));
  try {
    readEverything(dir / "half.db3");
    ADD_FAILURE() << "half a database read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(dir / "half.db3"), std::string::npos) << e.what();
  }
  auto b = good;
  ASSERT_GT(b.size(), 8192u);
  const std::string junk = "garbage garbage garbage";
  std::copy(junk.begin(), junk.end(), b.begin() + 100);
  for (std::size_t k = 4096; k < b.size(); k += 4096) b[k] ^= 0x5A;  // every page's first byte
  writeAll(dir / "pages.db3", b);
  try {
    readEverything(dir / "pages.db3");
    ADD_FAILURE() << "damaged pages read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(dir / "pages.db3"), std::string::npos) << e.what();
  }
  std::string text = "SQLite format 3";
  text.push_back('\0');
  text += std::string(300, 'x');
  writeAll(dir / "fake.db3", std::vector<std::uint8_t>(text.begin(), text.end()));
  expectInputError(dir / "fake.db3", "fake.db3");
  writeAll(dir / "empty.db3", {});
  expectInputError(dir / "empty.db3", "not a bag");
}

std::size_t findBytes(const std::vector<std::uint8_t>& b, const std::string& s,
                      std::size_t from = 0) {
  auto it = std::search(b.begin() + static_cast<std::ptrdiff_t>(from), b.end(), s.begin(), s.end());
  return it == b.end() ? std::string::npos : static_cast<std::size_t>(it - b.begin());
}

TEST(BagHostile, Rosbag1) {
  TempDir dir("bag_ros1");
  for (const std::string c : {"bz2", "lz4"}) {
    const auto good = readAll(kBags + "/mixed_ros1_" + c + ".bag");
    auto b = good;
    b[8] = '1';  // "#ROSBAG V1.0"
    writeAll(dir / "magic.bag", b);
    expectInputError(dir / "magic.bag", "not a bag");
    writeAll(
        dir / "half.bag",
        std::vector<std::uint8_t>(good.begin(), good.begin() + static_cast<long>(good.size() / 2)));
    expectInputError(dir / "half.bag", "truncated");
    const std::size_t comp = findBytes(good, "compression=" + c);
    ASSERT_NE(comp, std::string::npos);
    b = good;
    b[comp + 12] = 'q';
    writeAll(dir / "comp.bag", b);
    expectInputError(dir / "comp.bag", "unknown chunk compression");
    const std::size_t size = findBytes(good, "size=", comp > 40 ? comp - 40 : 0);
    ASSERT_NE(size, std::string::npos);
    b = good;
    b[size + 5] = 0xFF;
    b[size + 6] = 0xFF;
    b[size + 7] = 0xFF;
    b[size + 8] = 0x7F;  // 2 GiB declared: refused after decompression, never zero-filled
    writeAll(dir / "size.bag", b);
    expectInputError(dir / "size.bag", "chunk");
    b = good;
    const std::size_t data = findBytes(good, "op=\x05") + 200;
    for (std::size_t k = data; k < data + 16; ++k) b[k] ^= 0xA5;
    writeAll(dir / "data.bag", b);
    try {
      readEverything(dir / "data.bag");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(dir / "data.bag"), std::string::npos) << e.what();
    }
  }
}

// A deterministic mutation run over every fixture (the fuzz target's job in small): bytes
// flipped, zeroed or set to 0xFF near the start and anywhere, lengths cut; every read either
// succeeds or throws one of the library's errors, never anything else (run under ASan in
// scripts/test's sanitizer stage).
TEST(BagHostile, MutatedFixturesNeverCrash) {
  TempDir dir("bag_mutate");
  std::mt19937 rng(26);
  std::vector<std::string> files = kMixed;
  int errors = 0, reads = 0;
  for (const std::string& name : files) {
    const auto good = readAll(kBags + "/" + name);
    const std::string ext = fs::path(name).extension().string();
    for (int round = 0; round < 40; ++round) {
      auto b = good;
      const int edits = 1 + static_cast<int>(rng() % 4);
      for (int e = 0; e < edits; ++e) {
        const std::size_t at =
            (rng() % 2) ? rng() % std::min<std::size_t>(b.size(), 4096) : rng() % b.size();
        const unsigned what = rng() % 3;
        b[at] = what == 0 ? static_cast<std::uint8_t>(rng()) : what == 1 ? 0 : 0xFF;
      }
      if (rng() % 4 == 0) b.resize(rng() % b.size());
      const std::string path = dir / ("m" + ext);
      writeAll(path, b);
      try {
        readEverything(path);
        ++reads;
      } catch (const InputError&) {
        ++errors;
      } catch (const metricmap::CapacityError&) {
        ++errors;
      } catch (const metricmap::TopicSelectionError&) {
        ++errors;
      }
    }
  }
  std::cout << reads << " mutated bags read, " << errors << " refused\n";
  EXPECT_GT(errors, 0);
}

// --- hostile messages: CDR written here field by field ------------------------------------

struct Cdr {
  std::vector<std::uint8_t> b{0, 1, 0, 0};
  void align(std::size_t n) {
    while ((b.size() - 4) % n) b.push_back(0);
  }
  void u8(std::uint8_t v) { b.push_back(v); }
  void u32(std::uint32_t v) {
    align(4);
    for (int k = 0; k < 4; ++k) b.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  void str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size() + 1));
    b.insert(b.end(), s.begin(), s.end());
    b.push_back(0);
  }
};

struct FieldSpec {
  std::string name;
  std::uint32_t offset;
  std::uint8_t datatype;
  std::uint32_t count = 1;
};

std::vector<std::uint8_t> cloud(const std::vector<FieldSpec>& fields, std::uint32_t width,
                                std::uint32_t height, std::uint32_t point_step,
                                std::uint32_t row_step, std::uint32_t data_size,
                                std::uint32_t declared_size) {
  Cdr c;
  c.u32(5);
  c.u32(6);
  c.str("lidar");
  c.u32(height);
  c.u32(width);
  c.u32(static_cast<std::uint32_t>(fields.size()));
  for (const FieldSpec& f : fields) {
    c.str(f.name);
    c.u32(f.offset);
    c.u8(f.datatype);
    c.u32(f.count);
  }
  c.u8(0);
  c.u32(point_step);
  c.u32(row_step);
  c.u32(declared_size);
  for (std::uint32_t k = 0; k < data_size; ++k) c.u8(0);
  c.u8(1);
  return c.b;
}

const std::vector<FieldSpec> kXyz = {{"x", 0, 7}, {"y", 4, 7}, {"z", 8, 7}};

void expectBad(const std::vector<std::uint8_t>& m, const std::string& needle) {
  try {
    metricmap::decodePointCloud2(m.data(), m.size(), metricmap::MessageReader::Encoding::Cdr,
                                 "bag.db3: topic /p, message 0");
    ADD_FAILURE() << "decoded: " << needle;
  } catch (const std::runtime_error& e) {
    const std::string w = e.what();
    EXPECT_EQ(w.rfind("bag.db3: topic /p, message 0: ", 0), 0u) << w;
    EXPECT_NE(w.find(needle), std::string::npos) << w;
  }
}

TEST(PointCloud2, DecodesAGoodOneAndRefusesBadLayouts) {
  const auto good = cloud(kXyz, 2, 3, 12, 24, 72, 72);
  const auto m = metricmap::decodePointCloud2(good.data(), good.size(),
                                              metricmap::MessageReader::Encoding::Cdr, "m");
  EXPECT_EQ(m.cloud.points.size(), 6u);
  EXPECT_EQ(m.stamp, 5.000000006);
  expectBad(cloud({{"x", 0, 7}, {"y", 4, 7}, {"z", 10, 7}}, 2, 3, 12, 24, 72, 72), "point_step");
  expectBad(cloud({{"x", 0, 7}, {"y", 4, 7}, {"z", 6, 7}}, 2, 3, 12, 24, 72, 72), "overlap");
  expectBad(cloud({{"x", 0, 7}, {"y", 4, 7}, {"z", 8, 9}}, 2, 3, 12, 24, 72, 72),
            "unknown datatype");
  expectBad(cloud({{"x", 0, 7}, {"y", 4, 7}, {"z", 8, 7, 0}}, 2, 3, 12, 24, 72, 72), "count 0");
  expectBad(cloud(kXyz, 2, 3, 12, 20, 60, 60), "row_step");
  expectBad(cloud(kXyz, 2, 3, 12, 24, 48, 48), "not row_step");
  expectBad(cloud(kXyz, 2, 3, 12, 24, 72, 1000000), "sequence of 1000000");
  expectBad(cloud(kXyz, 0xFFFFFFFFu, 0xFFFFFFFFu, 12, 0xFFFFFFFFu, 0, 0), "row_step");
  expectBad(cloud(kXyz, 1u << 28, 1, 12, 12u << 28, 0, 0), "data holds 0 bytes");
  expectBad(cloud({{"a", 0, 7}}, 2, 3, 12, 24, 72, 72), "x, y and z");
  // Every prefix of a good message is refused without reading past it.
  for (std::size_t n = 0; n < good.size(); ++n) {
    std::vector<std::uint8_t> p(good.begin(), good.begin() + n);
    EXPECT_THROW(metricmap::decodePointCloud2(p.data(), p.size(),
                                              metricmap::MessageReader::Encoding::Cdr, "m"),
                 InputError)
        << n;
  }
}

// --- streaming: bags much larger than what reading them holds ------------------------------

// Peak resident memory (VmHWM, kB) since the last reset; reset: clear_refs 5 (Linux).
long peakRssKb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}
bool resetPeakRss() { return static_cast<bool>(std::ofstream("/proc/self/clear_refs") << "5"); }

// A PointCloud2 of n points (x y z intensity float32): point k of message m at (m, k, 1), k.
std::vector<std::uint8_t> bigCloud(std::uint32_t m, std::uint32_t n) {
  Cdr c;
  c.u32(m);
  c.u32(0);
  c.str("lidar");
  c.u32(1);
  c.u32(n);
  c.u32(4);
  std::uint32_t off = 0;
  for (const char* name : {"x", "y", "z", "intensity"}) {
    c.str(name);
    c.u32(off);
    c.u8(7);
    c.u32(1);
    off += 4;
  }
  c.u8(0);
  c.u32(16);
  c.u32(16 * n);
  c.u32(16 * n);
  c.b.reserve(c.b.size() + 16 * std::size_t(n) + 1);
  for (std::uint32_t k = 0; k < n; ++k) {
    const float v[4] = {static_cast<float>(m), static_cast<float>(k), 1.0f, static_cast<float>(k)};
    const auto* p = reinterpret_cast<const std::uint8_t*>(v);
    c.b.insert(c.b.end(), p, p + 16);
  }
  c.u8(1);
  return c.b;
}

void putLe(std::vector<std::uint8_t>& b, std::uint64_t v, int n) {
  for (int k = 0; k < n; ++k) b.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}
void putStr(std::vector<std::uint8_t>& b, const std::string& s) {
  putLe(b, s.size(), 4);
  b.insert(b.end(), s.begin(), s.end());
}
void putRecord(std::ofstream& out, std::uint8_t op, const std::vector<std::uint8_t>& content) {
  std::vector<std::uint8_t> h{op};
  putLe(h, content.size(), 8);
  out.write(reinterpret_cast<const char*>(h.data()), 9);
  out.write(reinterpret_cast<const char*>(content.data()),
            static_cast<std::streamsize>(content.size()));
}

constexpr std::uint32_t kBigMessages = 256, kBigPoints = 65536;  // 256 x 1 MiB

void writeBigDb3(const std::string& path) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(
      sqlite3_exec(db,
                   "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type "
                   "TEXT NOT NULL, serialization_format TEXT NOT NULL, offered_qos_profiles "
                   "TEXT NOT NULL); CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id "
                   "INTEGER NOT NULL, timestamp INTEGER NOT NULL, data BLOB NOT NULL); INSERT "
                   "INTO topics VALUES (1, '/points', 'sensor_msgs/msg/PointCloud2', 'cdr', "
                   "''); BEGIN;",
                   nullptr, nullptr, nullptr),
      SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  ASSERT_EQ(
      sqlite3_prepare_v2(db, "INSERT INTO messages(topic_id, timestamp, data) VALUES (1, ?, ?)", -1,
                         &s, nullptr),
      SQLITE_OK);
  for (std::uint32_t m = 0; m < kBigMessages; ++m) {
    const auto b = bigCloud(m, kBigPoints);
    sqlite3_bind_int64(s, 1, std::int64_t(m) * 100000000);
    sqlite3_bind_blob(s, 2, b.data(), static_cast<int>(b.size()), SQLITE_TRANSIENT);
    ASSERT_EQ(sqlite3_step(s), SQLITE_DONE);
    sqlite3_reset(s);
  }
  sqlite3_finalize(s);
  ASSERT_EQ(sqlite3_exec(db, "COMMIT;", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
}

// An MCAP file without summary: each message in its own uncompressed chunk (CRC 0: unchecked).
void writeBigMcap(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out.write("\x89MCAP0\r\n", 8);
  std::vector<std::uint8_t> c;
  putStr(c, "ros2");
  putStr(c, "test");
  putRecord(out, 0x01, c);
  c.clear();
  putLe(c, 1, 2);
  putStr(c, "sensor_msgs/msg/PointCloud2");
  putStr(c, "ros2msg");
  putLe(c, 0, 4);
  putRecord(out, 0x03, c);
  c.clear();
  putLe(c, 1, 2);
  putLe(c, 1, 2);
  putStr(c, "/points");
  putStr(c, "cdr");
  putLe(c, 0, 4);
  putRecord(out, 0x04, c);
  for (std::uint32_t m = 0; m < kBigMessages; ++m) {
    const auto data = bigCloud(m, kBigPoints);
    std::vector<std::uint8_t> msg{0x05};
    putLe(msg, 2 + 4 + 8 + 8 + data.size(), 8);
    putLe(msg, 1, 2);
    putLe(msg, m, 4);
    putLe(msg, std::uint64_t(m) * 100000000, 8);
    putLe(msg, std::uint64_t(m) * 100000000, 8);
    msg.insert(msg.end(), data.begin(), data.end());
    c.clear();
    putLe(c, std::uint64_t(m) * 100000000, 8);
    putLe(c, std::uint64_t(m) * 100000000, 8);
    putLe(c, msg.size(), 8);
    putLe(c, 0, 4);
    putStr(c, "");
    putLe(c, msg.size(), 8);
    c.insert(c.end(), msg.begin(), msg.end());
    putRecord(out, 0x06, c);
  }
  putRecord(out, 0x0F, std::vector<std::uint8_t>(4, 0));
  c.assign(20, 0);
  putRecord(out, 0x02, c);
  out.write("\x89MCAP0\r\n", 8);
}

TEST(BagStreaming, ReadsBagsMuchLargerThanItsPeakMemory) {
  TempDir dir("bag_stream");
  for (const char* name : {"big.db3", "big.mcap"}) {
    const std::string path = dir / name;
    if (std::string(name) == "big.db3") {
      writeBigDb3(path);
    } else {
      writeBigMcap(path);
    }
    const auto bytes = fs::file_size(path);
    ASSERT_GT(bytes, 256u << 20);
    if (!resetPeakRss()) GTEST_SKIP() << "cannot reset the peak RSS (/proc/self/clear_refs)";
    const long before = peakRssKb();
    {
      metricmap::BagSource bag(path, {});
      ASSERT_EQ(bag.size(), kBigMessages);
      for (std::size_t i = 0; i < bag.size(); ++i) {
        const metricmap::Scan s = bag.scan(i);
        ASSERT_EQ(s.points.size(), kBigPoints);
        ASSERT_EQ(s.points[kBigPoints - 1].x, static_cast<float>(i));
        ASSERT_EQ(s.points[kBigPoints - 1].y, static_cast<float>(kBigPoints - 1));
      }
    }
    const long peak = peakRssKb();
    std::cout << name << ": " << bytes / (1 << 20) << " MiB read with a peak RSS of " << peak / 1024
              << " MiB (" << before / 1024 << " MiB before reading)\n";
    RecordProperty(std::string(name) + "_peak_rss_kb", std::to_string(peak));
    EXPECT_LT(peak - before, 64 * 1024) << name;  // well below the bag's 256+ MiB
    fs::remove(path);
  }
}

}  // namespace
