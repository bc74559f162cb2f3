// Special files where a reader expects a regular one: a FIFO named like a bag is refused before
// any open (opening it would block until a writer came), and a folder source refuses an entry
// named like a scan that is a directory, a FIFO, a dangling link or a symbolic link loop (it was
// skipped, and the run had one frame fewer without a word).
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/bag_reader.h"
#include "temp_dir.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

/// A float32 (n, 3) .npy array of points on a line, as np.save writes it.
void writeNpy(const std::string& path, int n) {
  std::string header =
      "{'descr': '<f4', 'fortran_order': False, 'shape': (" + std::to_string(n) + ", 3), }";
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const std::uint16_t len = static_cast<std::uint16_t>(header.size());
  out.write(reinterpret_cast<const char*>(&len), 2);
  out << header;
  for (int i = 0; i < n; ++i) {
    const float p[3] = {1.0f + 0.01f * static_cast<float>(i), 2.0f, 0.5f};
    out.write(reinterpret_cast<const char*>(p), sizeof p);
  }
}

/// `fn` throws InputError whose message contains every needle.
template <typename Fn>
void expectRefused(Fn fn, const std::vector<std::string>& needles) {
  try {
    fn();
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    for (const std::string& n : needles)
      EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what() << " / " << n;
  }
}

TEST(SpecialFiles, FifoNamedLikeABagIsRefusedByEveryBagEntryPoint) {
  TempDir dir("bag_fifo");
  for (const char* name : {"f.mcap", "f.db3", "f.bag", "F.MCAP"}) {
    SCOPED_TRACE(name);
    const std::string path = dir / name;
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    expectRefused([&] { openBag(path); }, {path, "not a regular file", "FIFO"});
    expectRefused([&] { openScanSource(path); }, {path, "not a regular file"});
    ScanSourceOptions bag;
    bag.format = "bag";
    expectRefused([&] { openScanSource(path, bag); }, {path, "not a regular file"});
  }
  // A directory named like a bag file (no metadata.yaml: not a rosbag2 folder) with format bag.
  fs::create_directories(dir.path / "d.mcap" / "x");
  ScanSourceOptions bag;
  bag.format = "bag";
  expectRefused([&] { openScanSource(dir / "d.mcap", bag); }, {"d.mcap"});
}

struct FolderCase {
  std::string entry;  ///< named like a scan
  std::string kind;   ///< what the message calls it
  void (*make)(const std::string& path);
};

const std::vector<FolderCase> kFolderCases = {
    {"004.npy", "a directory", [](const std::string& p) { fs::create_directories(p); }},
    {"004.pcd", "a FIFO", [](const std::string& p) { ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0); }},
    {"004.bin", "a dangling link",
     [](const std::string& p) { fs::create_symlink(p + ".missing", p); }},
    {"004.ply", "a symbolic link loop",
     [](const std::string& p) {
       fs::create_symlink(p + ".b", p);
       fs::create_symlink(p, p + ".b");
     }},
    {"004.npy", "a directory",  // a link to a directory
     [](const std::string& p) {
       fs::create_directories(p + ".target");
       fs::create_symlink(p + ".target", p);
     }},
};

TEST(SpecialFiles, FolderSourceRefusesEntriesNamedLikeScansThatAreNotFiles) {
  for (const FolderCase& c : kFolderCases) {
    SCOPED_TRACE(c.entry + " as " + c.kind);
    TempDir dir("folder_special");
    for (int k = 0; k < 3; ++k) writeNpy(dir / ("00" + std::to_string(k) + ".npy"), 200);
    // The oracle: the folder of the three scans alone has three frames.
    ASSERT_EQ(openScanSource(dir.path.string())->size(), 3u);
    c.make(dir / c.entry);
    expectRefused([&] { openScanSource(dir.path.string()); },
                  {dir.path.string(), c.entry, "named like a scan", c.kind});
    ScanSourceOptions folder;
    folder.format = "folder";
    expectRefused([&] { openScanSource(dir.path.string(), folder); }, {c.entry, c.kind});
  }
}

TEST(SpecialFiles, EntriesNotNamedLikeScansStayIgnored) {
  TempDir dir("folder_other");
  for (int k = 0; k < 2; ++k) writeNpy(dir / ("00" + std::to_string(k) + ".npy"), 200);
  fs::create_directories(dir.path / "sub");
  ASSERT_EQ(::mkfifo((dir / "pipe.txt").c_str(), 0600), 0);
  fs::create_symlink(dir / "nowhere", dir / "dangling.yaml");
  EXPECT_EQ(openScanSource(dir.path.string())->size(), 2u);
}

}  // namespace
}  // namespace metricmap
