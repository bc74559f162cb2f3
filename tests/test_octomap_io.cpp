// OctoMap files: ours read by liboctomap voxel for voxel, liboctomap's (and the real geb079.bt)
// read by ours, hostile and truncated files refused with InputError before liboctomap sees them.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <octomap/AbstractOcTree.h>
#include <octomap/OcTree.h>

#include <gtest/gtest.h>

#include "metricmap/exceptions.h"
#include "metricmap/occupancy/octomap_io.h"
#include "occupancy_scans.h"
#include "scratch_files.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;
constexpr std::int64_t kOcto = 32768;

fs::path tempDir() {
  static const metricmap::test_support::ScratchDir dir("metricmap_octomap_io_");  // removed at exit
  return dir.path;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string writeBytes(const std::string& name, const std::string& bytes) {
  const fs::path p = tempDir() / name;
  std::ofstream(p, std::ios::binary) << bytes;
  return p.string();
}

// Every voxel of a liboctomap tree (pruned leaves expanded): state and log-odds.
struct Voxels {
  std::size_t count = 0, occupied = 0, state_mismatch = 0, value_mismatch = 0, missing = 0;
};

Voxels compareTree(const octomap::OcTree& tree, const LogOddsMap& map, bool values) {
  Voxels v;
  const unsigned depth = tree.getTreeDepth();
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const octomap::OcTreeKey base = it.getIndexKey();
    const std::int64_t edge = std::int64_t{1} << (depth - it.getDepth());
    const bool occ = tree.isNodeOccupied(*it);
    for (std::int64_t z = 0; z < edge; ++z)
      for (std::int64_t y = 0; y < edge; ++y)
        for (std::int64_t x = 0; x < edge; ++x) {
          ++v.count;
          v.occupied += occ ? 1 : 0;
          const std::optional<float> l =
              map.logOdds({base[0] + x - kOcto, base[1] + y - kOcto, base[2] + z - kOcto});
          if (!l) {
            ++v.missing;
            continue;
          }
          v.state_mismatch += map.isOccupied(*l) != occ ? 1 : 0;
          v.value_mismatch += values && std::abs(*l - it->getLogOdds()) > 1e-6f ? 1 : 0;
        }
  }
  return v;
}

LogOddsMap kittiMap() {
  LogOddsParams p;
  p.resolution = 0.2;
  p.max_range = 30.0;
  LogOddsMap map(p);
  for (std::size_t f : {0u, 3u}) {
    const test::WorldScan s = test::subsample(test::kittiWorldScan(f), 4);
    map.insertScan(s.points, s.origin);
  }
  return map;
}

TEST(OctomapIo, OursReadByLiboctomap) {
  const LogOddsMap map = kittiMap();
  ASSERT_GT(map.knownVoxels(), 100000u);
  const std::string bt = (tempDir() / "ours.bt").string();
  const std::string ot = (tempDir() / "ours.ot").string();
  writeOctomap(map, bt);
  writeOctomap(map, ot);

  octomap::OcTree from_bt(0.1);
  ASSERT_TRUE(from_bt.readBinary(bt));
  EXPECT_DOUBLE_EQ(from_bt.getResolution(), 0.2);
  const Voxels b = compareTree(from_bt, map, false);
  EXPECT_EQ(b.count, map.knownVoxels());
  EXPECT_EQ(b.missing, 0u);
  EXPECT_EQ(b.state_mismatch, 0u);
  EXPECT_EQ(b.occupied, map.occupiedVoxels());

  std::unique_ptr<octomap::AbstractOcTree> any(octomap::AbstractOcTree::read(ot));
  auto* from_ot = dynamic_cast<octomap::OcTree*>(any.get());
  ASSERT_NE(from_ot, nullptr);
  const Voxels o = compareTree(*from_ot, map, true);
  EXPECT_EQ(o.count, map.knownVoxels());
  EXPECT_EQ(o.missing, 0u);
  EXPECT_EQ(o.value_mismatch, 0u);

  // and back into ours: .ot keeps every log-odds, .bt the states
  const LogOddsMap back_ot = readOctomap(ot);
  EXPECT_EQ(back_ot.knownVoxels(), map.knownVoxels());
  std::size_t same = 0;
  map.forEachKnown([&](const VoxelKey& k, float l) {
    const std::optional<float> m = back_ot.logOdds(k);
    same += (m && *m == l) ? 1 : 0;
  });
  EXPECT_EQ(same, map.knownVoxels());
  const LogOddsMap back_bt = readOctomap(bt);
  EXPECT_EQ(back_bt.knownVoxels(), map.knownVoxels());
  EXPECT_EQ(back_bt.occupiedVoxels(), map.occupiedVoxels());
}

TEST(OctomapIo, LiboctomapsFileReadByOurs) {
  const test::WorldScan s = test::subsample(test::kittiWorldScan(1), 4);
  octomap::OcTree tree(0.2);
  octomap::Pointcloud pc;
  for (const auto& p : s.points) pc.push_back(p.x, p.y, p.z);
  tree.insertPointCloud(pc, octomap::point3d(s.origin.x(), s.origin.y(), s.origin.z()), 30.0);
  const std::string bt = (tempDir() / "theirs.bt").string();
  const std::string ot = (tempDir() / "theirs.ot").string();
  ASSERT_TRUE(tree.writeBinaryConst(bt));
  ASSERT_TRUE(tree.write(ot));
  const LogOddsMap from_ot = readOctomap(ot);
  const Voxels o = compareTree(tree, from_ot, true);
  EXPECT_GT(o.count, 50000u);
  EXPECT_EQ(o.count, from_ot.knownVoxels());
  EXPECT_EQ(o.missing + o.value_mismatch, 0u);
  const LogOddsMap from_bt = readOctomap(bt);
  const Voxels b = compareTree(tree, from_bt, false);
  EXPECT_EQ(b.count, from_bt.knownVoxels());
  EXPECT_EQ(b.missing + b.state_mismatch, 0u);
}

TEST(OctomapIo, RealMapGeb079) {
  const std::string path = dataPath("octomap_geb079/geb079.bt");
  octomap::OcTree tree(0.1);
  ASSERT_TRUE(tree.readBinary(path));
  const LogOddsMap map = readOctomap(path);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.08);
  const Voxels v = compareTree(tree, map, false);
  std::printf("geb079.bt: %zu nodes, %zu voxels known (%zu occupied)\n", tree.size(), v.count,
              v.occupied);
  EXPECT_EQ(tree.size(), 532566u);  // SOURCE.md
  EXPECT_EQ(v.count, map.knownVoxels());
  EXPECT_EQ(v.missing + v.state_mismatch, 0u);
  EXPECT_EQ(v.occupied, map.occupiedVoxels());
  // written again by us, read by liboctomap: the same occupied and free voxels
  const std::string again = (tempDir() / "geb079_again.bt").string();
  writeOctomap(map, again);
  octomap::OcTree tree2(0.1);
  ASSERT_TRUE(tree2.readBinary(again));
  const Voxels w = compareTree(tree2, map, false);
  EXPECT_EQ(w.count, v.count);
  EXPECT_EQ(w.occupied, v.occupied);
  EXPECT_EQ(w.missing + w.state_mismatch, 0u);
}

TEST(OctomapIo, CorruptAndTruncatedFilesAreRefused) {
  const std::string good = slurp(dataPath("octomap_geb079/geb079.bt"));
  ASSERT_EQ(good.size(), 208986u);
  const std::size_t data = good.find("data\n") + 5;
  std::vector<std::pair<std::string, std::string>> cases = {
      {"empty.bt", ""},
      {"magic.bt", "# Octomap OcTree something\n" + good.substr(good.find('\n') + 1)},
      {"header_only.bt", good.substr(0, data - 5)},
      {"no_data_bytes.bt", good.substr(0, data)},
      {"half.bt", good.substr(0, good.size() / 2)},
      {"minus_one.bt", good.substr(0, good.size() - 1)},
      {"plus_one.bt", good + "x"},
      {"all_inner.bt", good.substr(0, data) + std::string(4096, '\xff')},
  };
  std::string bad_res = good;
  bad_res.replace(bad_res.find("res 0.08"), 8, "res 0.00");
  cases.emplace_back("res0.bt", bad_res);
  // every header number through the checked parser, every key once
  for (const auto& [name, res] :
       std::vector<std::pair<std::string, std::string>>{{"res_junk.bt", "res 0.08abc"},
                                                        {"res_tiny.bt", "res 1e-300"},
                                                        {"res_hex.bt", "res 0x1p-4"},
                                                        {"res_two.bt", "res 0.08 0.08"},
                                                        {"res_twice.bt", "res 0.08\nres 0.16"}}) {
    std::string text = good;
    text.replace(text.find("res 0.08"), 8, res);
    cases.emplace_back(name, text);
  }
  std::string size_junk = good;
  size_junk.replace(size_junk.find("size 532566"), 11, "size 532566x");
  cases.emplace_back("size_junk.bt", size_junk);
  std::string bad_size = good;
  bad_size.replace(bad_size.find("size 532566"), 11, "size 532567");
  cases.emplace_back("size.bt", bad_size);
  // a .ot whose tree claims children below depth 16, and one with a NaN log-odds
  std::string deep = "# Octomap OcTree file\nid OcTree\nsize 18\nres 0.1\ndata\n";
  for (int i = 0; i < 18; ++i) deep += std::string("\0\0\0\0\x01", 5);
  cases.emplace_back("deep.ot", deep);
  std::string nan_ot = "# Octomap OcTree file\nid OcTree\nsize 1\nres 0.1\ndata\n";
  nan_ot += std::string("\x00\x00\xc0\x7f\x00", 5);
  cases.emplace_back("nan.ot", nan_ot);
  cases.emplace_back("color.ot", "# Octomap OcTree file\nid ColorOcTree\nsize 1\nres 0.1\ndata\n" +
                                     std::string(5, '\0'));
  for (const auto& [name, bytes] : cases) {
    const std::string path = writeBytes(name, bytes);
    try {
      readOctomap(path);
      ADD_FAILURE() << name << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(readOctomap("/no/such/map.bt"), InputError);
}

TEST(OctomapIo, WritesAreAtomicAndBounded) {
  LogOddsParams p;
  p.resolution = 0.1;
  LogOddsMap map(p);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back({4000.0f, 0.0f, 0.0f});  // 40000 voxels: beyond OctoMap's 32768
  map.insertScan(cloud, Eigen::Vector3f(3999.0f, 0.0f, 0.0f));
  const fs::path out = tempDir() / "far.bt";
  fs::remove(out);
  EXPECT_THROW(writeOctomap(map, out.string()), CapacityError);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_THROW(writeOctomap(map, (tempDir() / "map.xyz").string()), std::invalid_argument);
  LogOddsMap small(p);
  pcl::PointCloud<pcl::PointXYZ> near;
  near.push_back({1.0f, 0.0f, 0.0f});
  small.insertScan(near, Eigen::Vector3f::Zero());
  try {
    writeOctomap(small, "/no/such/dir/m.bt");
    ADD_FAILURE() << "wrote into a missing directory";
  } catch (const CapacityError&) {
    ADD_FAILURE() << "a 1 m map does not exceed the key space";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/dir/m.bt"), std::string::npos);
  }
  // nothing but the written files in the directory: no temporaries left behind
  for (const auto& entry : fs::directory_iterator(tempDir()))
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace metricmap
