#include "metricmap/datasets/folder_source.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <system_error>

#include "metricmap/common/parse_number.h"
#include "metricmap/datasets/reference_file.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/file_identity.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/scan_file.h"

namespace metricmap {
namespace fs = std::filesystem;

bool naturalLess(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const bool da = std::isdigit(static_cast<unsigned char>(a[i])) != 0;
    const bool db = std::isdigit(static_cast<unsigned char>(b[j])) != 0;
    if (da && db) {
      std::size_t ei = i, ej = j;
      while (ei < a.size() && std::isdigit(static_cast<unsigned char>(a[ei]))) ++ei;
      while (ej < b.size() && std::isdigit(static_cast<unsigned char>(b[ej]))) ++ej;
      // Compare the runs as numbers: strip leading zeros, then length, then digits.
      std::size_t zi = i, zj = j;
      while (zi + 1 < ei && a[zi] == '0') ++zi;
      while (zj + 1 < ej && b[zj] == '0') ++zj;
      if (ei - zi != ej - zj) return ei - zi < ej - zj;
      const int c = a.compare(zi, ei - zi, b, zj, ej - zj);
      if (c != 0) return c < 0;
      if (ei - i != ej - j) return ei - i < ej - j;  // "01" after "1"
      i = ei;
      j = ej;
    } else {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

namespace {

std::string scanExtension(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* e : {".pcd", ".ply", ".bin", ".npy"}) {
    if (ext == e) return ext;
  }
  return "";
}

/// What an entry named like a scan is when it is not a regular file ("" when it is one).
std::string notRegular(const fs::path& p) {
  std::error_code ec;
  const fs::file_status st = fs::status(p, ec);  // follows links
  if (fs::is_regular_file(st)) return "";
  if (ec) {
    std::error_code lec;
    if (ec == std::errc::too_many_symbolic_link_levels) return "a symbolic link loop";
    if (fs::is_symlink(fs::symlink_status(p, lec))) return "a dangling link (" + ec.message() + ")";
    return "unreadable (" + ec.message() + ")";
  }
  if (fs::is_directory(st)) return "a directory";
  if (fs::is_fifo(st)) return "a FIFO";
  if (fs::is_socket(st)) return "a socket";
  return "a device or special file";
}

std::vector<std::string> listFolder(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (scanExtension(it->path()).empty()) continue;
    // Named like a scan but not a file: refused, never skipped (a frame would silently vanish)
    if (const std::string what = notRegular(it->path()); !what.empty()) {
      throw InputError(dir + ": " + it->path().filename().string() +
                       " is named like a scan but is " + what);
    }
    names.push_back(it->path().filename().string());
  }
  if (ec) throw InputError(dir + ": cannot list (" + ec.message() + ")");
  std::sort(names.begin(), names.end(), naturalLess);
  std::vector<std::string> paths;
  paths.reserve(names.size());
  std::map<std::pair<std::uint64_t, std::uint64_t>, std::string> seen;
  for (const std::string& n : names) {
    paths.push_back((fs::path(dir) / n).string());
    const FileIdentity id = fileIdentity(paths.back());
    const auto [it, fresh] = seen.emplace(std::make_pair(id.device, id.inode), n);
    if (id.exists && !fresh) {
      throw InputError(dir + ": " + n + " and " + it->second +
                       " are the same file (a link): a scan would be read twice");
    }
  }
  return paths;
}

std::vector<std::string> readList(const std::string& list) {
  std::ifstream in = openRegularFile(list, std::ios::in);
  const fs::path base = fs::path(list).parent_path();
  std::vector<std::string> paths;
  std::map<std::pair<std::uint64_t, std::uint64_t>, std::pair<std::size_t, std::string>> seen;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    fs::path p(line);
    if (p.is_relative()) p = base / p;
    if (scanExtension(p).empty()) {
      throw InputError(list + ": line " + std::to_string(n) +
                       " does not name a .pcd, .ply, .bin or .npy file");
    }
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) {
      throw InputError(list + ": line " + std::to_string(n) + ": " + p.string() +
                       " is not a readable file");
    }
    // A scan named twice (however spelled: a relative and an absolute path, a link) would be
    // registered and mapped twice.
    const FileIdentity id = fileIdentity(p.string());
    const auto [it, fresh] =
        seen.emplace(std::make_pair(id.device, id.inode), std::make_pair(n, line));
    if (id.exists && !fresh) {
      throw InputError(list + ": line " + std::to_string(n) + " ('" + quoteForMessage(line) +
                       "') names the scan of line " + std::to_string(it->second.first) + " ('" +
                       quoteForMessage(it->second.second) + "') again: a scan is listed once");
    }
    paths.push_back(p.string());
  }
  if (in.bad()) throw InputError(list + ": read error");
  return paths;
}

}  // namespace

std::vector<std::string> folderScanPaths(const std::string& path) {
  std::error_code ec;
  return fs::is_directory(path, ec) ? listFolder(path) : readList(path);
}

namespace {

class FolderSource : public ScanSource {
 public:
  FolderSource(const std::string& path, const ScanSourceOptions& o) {
    std::error_code ec;
    const bool dir = fs::is_directory(path, ec);
    files_ = folderScanPaths(path);
    if (files_.empty()) {
      throw InputError(path + (dir ? ": no .pcd, .ply, .bin or .npy scan in this folder"
                                   : ": the list names no scan"));
    }
    const std::string ext = scanExtension(files_.front());
    for (const std::string& f : files_) {
      if (scanExtension(f) != ext) {
        throw InputError(path + ": mixed scan formats (" + files_.front() + " and " + f +
                         "); keep one format per sequence");
      }
    }
    info_.kind = "folder";
    info_.path = path;
    const fs::path base = dir ? fs::path(path) : fs::path(path).parent_path();
    const std::string times = !o.times.empty() ? o.times : (base / "times.txt").string();
    if (!o.times.empty() || fs::exists(times, ec)) {
      info_.stamps = readStampsFile(times, files_.size());
    }
    const std::string poses =
        !o.reference_poses.empty() ? o.reference_poses : (base / "poses.txt").string();
    if (!o.reference_poses.empty() || fs::exists(poses, ec)) {
      info_.reference = readReferencePoses(poses, files_.size());
      if (info_.reference.stamps.empty()) info_.reference.stamps = info_.stamps;
      info_.reference_path = poses;
    }
    // Per-point times: told from the first scan (every scan of a sequence has the same fields).
    info_.point_times = !readScanFile(files_.front()).point_times.empty();
  }

  std::size_t size() const override { return files_.size(); }
  const SourceInfo& info() const override { return info_; }

  Scan scan(std::size_t i) override {
    if (i >= files_.size()) {
      throw InputError(info_.path + ": no scan " + std::to_string(i) + " (" +
                       std::to_string(files_.size()) + " scans, numbered from 0)");
    }
    ScanFile f = readScanFile(files_[i]);
    if (f.point_times.empty() != !info_.point_times) {
      throw InputError(files_[i] +
                       (info_.point_times ? ": no per-point time field, unlike "
                                          : ": a per-point time field, unlike ") +
                       files_.front());
    }
    Scan s;
    s.index = i;
    s.name = files_[i];
    s.points = std::move(f.points);
    s.intensity = std::move(f.intensity);
    s.point_times = std::move(f.point_times);
    if (!info_.stamps.empty()) s.stamp = info_.stamps[i];
    return s;
  }

 private:
  std::vector<std::string> files_;
  SourceInfo info_;
};

}  // namespace

std::unique_ptr<ScanSource> openFolderSource(const std::string& path,
                                             const ScanSourceOptions& options) {
  return std::make_unique<FolderSource>(path, options);
}

}  // namespace metricmap
