#include "metricmap/io/bag_reader.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/mcap_reader.h"
#include "metricmap/io/rosbag1_reader.h"
#include "metricmap/io/rosbag2_sqlite.h"

namespace metricmap {
namespace fs = std::filesystem;
namespace {

std::string lowerExtension(const fs::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

bool bagExtension(const fs::path& p) {
  const std::string e = lowerExtension(p);
  return e == ".db3" || e == ".mcap" || e == ".bag";
}

// The storage file of a rosbag2 folder: its one .db3 or .mcap.
std::string storageFile(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string x = lowerExtension(e.path());
    if (x == ".db3" || x == ".mcap") files.push_back(e.path().string());
  }
  if (ec) throw InputError(dir + ": cannot list the folder (" + ec.message() + ")");
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(dir + ": a rosbag2 folder without a .db3 or .mcap file");
  if (files.size() > 1)
    throw InputError(dir + ": a bag split in " + std::to_string(files.size()) +
                     " files; give one file (" + files.front() + ", ...)");
  requireRegularFile(files.front());  // a FIFO or directory named like storage: said so
  return files.front();
}

}  // namespace

bool looksLikeBag(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return fs::exists(fs::path(path) / "metadata.yaml", ec);
  return bagExtension(path);
}

std::unique_ptr<BagReader> openBag(const std::string& path) {
  std::error_code ec;
  const std::string file = fs::is_directory(path, ec) ? storageFile(path) : path;
  // stat before open: opening a FIFO named like a bag would block until a writer came
  std::ifstream in = openRegularFile(file);
  char magic[16] = {};
  in.read(magic, sizeof magic);
  const std::size_t got = static_cast<std::size_t>(in.gcount());
  in.close();
  if (got >= 8 && std::memcmp(magic, kMcapMagic, 8) == 0) return openMcap(file);
  if (got >= 16 && std::memcmp(magic, "SQLite format 3", 16) == 0) return openRosbag2Sqlite(file);
  if (got >= 13 && std::memcmp(magic, "#ROSBAG V2.0\n", 13) == 0) return openRosbag1(file);
  throw InputError(file + ": not a bag (no MCAP, SQLite or ROS 1 bag magic in its first bytes)");
}

}  // namespace metricmap
