#include "metricmap/datasets/kitti_sequence.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/parse_number.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

/// 12 numbers (row-major 3x4) through the checked parser, then the rigid-transform check.
/// \throws InputError "WHERE is not 12 finite numbers" or "WHERE: the 3x3 part is not a ..."
Eigen::Isometry3d parse12(std::istream& is, const std::string& where) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  std::string token;
  try {
    for (int i = 0; i < 12; ++i) {
      if (!(is >> token)) throw std::invalid_argument("");
      m(i / 4, i % 4) = parseFiniteDouble(token, where);
    }
  } catch (const std::invalid_argument&) {
    throw InputError(where + " is not 12 finite numbers");
  }
  if (is >> token) throw InputError(where + " is not 12 finite numbers");
  try {
    checkRigidTransform(m, where);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  Eigen::Isometry3d t;
  t.matrix() = m;
  return t;
}

}  // namespace

Eigen::Isometry3d readKittiCalibTr(const std::string& path) {
  std::ifstream in = openRegularFile(path, std::ios::in);
  std::string line;
  std::optional<Eigen::Isometry3d> tr;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    std::istringstream is(line);
    std::string key;
    is >> key;
    if (key != "Tr:") continue;
    // two Tr lines: which one is meant is unknown, so neither is used
    if (tr) throw InputError(path + ": a second 'Tr:' line (line " + std::to_string(n) + ")");
    tr = parse12(is, path + ": Tr (line " + std::to_string(n) + ")");
  }
  if (in.bad()) throw InputError(path + ": read error");
  if (!tr) throw InputError(path + ": no 'Tr:' line (velodyne -> camera 0)");
  return *tr;
}

std::vector<Eigen::Isometry3d> readKittiPoses(const std::string& path, std::size_t frames) {
  std::ifstream in = openRegularFile(path, std::ios::in);
  std::vector<Eigen::Isometry3d> poses;
  std::string line;
  for (std::size_t n = 1; poses.size() < frames && std::getline(in, line); ++n) {
    std::istringstream is(line);
    poses.push_back(parse12(is, path + ": line " + std::to_string(n)));
  }
  if (poses.size() < frames) {
    throw InputError(path + ": " + std::to_string(poses.size()) + " pose(s), frames up to " +
                     std::to_string(frames - 1) + " asked");
  }
  return poses;
}

std::vector<std::size_t> parseFrameList(const std::string& text, std::size_t max_frames) {
  std::vector<std::size_t> frames;
  std::size_t total = 0;
  std::istringstream is(text);
  auto number = [&](const std::string& s) {
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 9) {
      throw std::invalid_argument("frame list: '" + s + "' is not a frame number");
    }
    // As every count option: decimal without a leading zero (010 is not silently 10, nor 8).
    if (s.size() > 1 && s[0] == '0') {
      throw std::invalid_argument("frame list: '" + s +
                                  "' has a leading zero: write the frame number without it");
    }
    return static_cast<std::size_t>(std::stoul(s));
  };
  if (!text.empty() && text.back() == ',')  // getline drops a trailing empty item
    throw std::invalid_argument("frame list '" + text + "' ends in an empty item");
  for (std::string item; std::getline(is, item, ',');) {
    const auto dash = item.find('-');
    const std::size_t a = number(item.substr(0, dash));
    const std::size_t b = dash == std::string::npos ? a : number(item.substr(dash + 1));
    if (b < a) throw std::invalid_argument("frame list: range '" + item + "' runs backwards");
    total += b - a + 1;
    if (total > max_frames) {
      throw std::invalid_argument("frame list '" + text + "' names more than " +
                                  std::to_string(max_frames) + " frames");
    }
    for (std::size_t f = a; f <= b; ++f) frames.push_back(f);
  }
  if (frames.empty()) throw std::invalid_argument("frame list is empty");
  return frames;
}

std::string KittiSequence::scan(std::size_t frame) const {
  char name[32];
  std::snprintf(name, sizeof name, "%06zu.bin", frame);
  return root + "/sequences/" + sequence + "/velodyne/" + name;
}

Eigen::Isometry3d kittiScanToWorld(const Eigen::Isometry3d& pose, const Eigen::Isometry3d& tr,
                                   KittiWorld world) {
  if (world == KittiWorld::Camera) return pose * tr;
  // KITTI's Tr is orthonormal only to ~1e-7; invert the matrix, not just its rotation.
  Eigen::Isometry3d tr_inv;
  tr_inv.matrix() = tr.matrix().inverse();
  return tr_inv * pose * tr;
}

Eigen::Isometry3d kittiPoseOfScan(const Eigen::Isometry3d& scan_to_world,
                                  const Eigen::Isometry3d& tr, KittiWorld world) {
  return world == KittiWorld::Camera ? scan_to_world * tr.inverse() : scan_to_world;
}

}  // namespace metricmap
