#include "metricmap/datasets/scan_source.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "metricmap/datasets/bag_source.h"
#include "metricmap/datasets/carmen_source.h"
#include "metricmap/datasets/folder_source.h"
#include "metricmap/datasets/kitti_source.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace fs = std::filesystem;
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool looksLikeLaserLog(const std::string& path) {
  const std::string p = lower(path);
  for (const char* z : {"", ".gz", ".bz2"}) {
    for (const char* e : {".clf", ".log"}) {
      if (endsWith(p, std::string(e) + z)) return true;
    }
  }
  return false;
}

}  // namespace

std::string ignoredSourceOption(const std::string& kind, const std::string& option) {
  const std::string what = kind == "carmen"   ? "a CARMEN log"
                           : kind == "folder" ? "a folder or list of scans"
                           : kind == "bag"    ? "a bag"
                                              : "a KITTI root";
  if (kind.empty()) return "";
  if (option == "sequence" && kind != "kitti")
    return "on " + what + ": only a KITTI root has sequences";
  if ((option == "times" || option == "reference_poses") && kind == "carmen")
    return "on a CARMEN log: its lines carry the scans' stamps and odometry poses";
  if (option == "times" && kind == "bag") return "on a bag: its messages carry the scans' stamps";
  if (option == "topic" && kind != "bag") return "on " + what + ": only a bag has topics";
  return "";
}

std::string scanSourceKind(const std::string& path, const std::string& format) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::string();
  const bool dir = fs::is_directory(path, ec);
  if (format == "bag" || (format == "auto" && looksLikeBag(path))) return "bag";
  if (format == "kitti" || (format == "auto" && dir && looksLikeKittiRoot(path))) return "kitti";
  if (format == "carmen" || (format == "auto" && !dir && looksLikeLaserLog(path))) return "carmen";
  if (format == "folder" || (format == "auto" && (dir || endsWith(lower(path), ".txt"))))
    return "folder";
  return std::string();
}

std::unique_ptr<ScanSource> openScanSource(const std::string& path,
                                           const ScanSourceOptions& options) {
  const std::string& f = options.format;
  if (f != "auto" && f != "kitti" && f != "folder" && f != "carmen" && f != "bag") {
    throw std::invalid_argument("source format must be auto, kitti, folder, carmen or bag, got '" +
                                f + "'");
  }
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": no such file or folder");
  const bool dir = fs::is_directory(path, ec);
  if (f == "bag" || (f == "auto" && looksLikeBag(path))) return openBagSource(path, options);
  if (f == "kitti" || (f == "auto" && dir && looksLikeKittiRoot(path))) {
    if (!dir) throw InputError(path + ": a KITTI root must be a folder");
    return openKittiSource(path, options);
  }
  if (f == "carmen" || (f == "auto" && !dir && looksLikeLaserLog(path))) {
    if (dir) throw InputError(path + ": a CARMEN log is a file, not a folder");
    return openCarmenSource(path);
  }
  if (f == "folder" || dir || endsWith(lower(path), ".txt")) return openFolderSource(path, options);
  throw InputError(path +
                   ": not a scan source (a KITTI root, a folder of .pcd/.ply/.bin/.npy scans, a "
                   ".txt list of scans or a CARMEN .clf/.log[.gz|.bz2] log)");
}

}  // namespace metricmap
