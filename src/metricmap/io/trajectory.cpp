#include "metricmap/io/trajectory.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <Eigen/Geometry>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/trajectory_text.h"

namespace metricmap {
namespace {

using detail::forEachDataLine;
using detail::readBoundedText;

/// "PATH: line N".
std::string where(const std::string& path, std::size_t line) {
  return detail::lineWhere(path, line);
}

double number(std::string_view token, const std::string& path, std::size_t line) {
  return detail::lineNumber(token, path, line);
}

/// Largest | |q| - 1 | accepted for a TUM quaternion before it is normalised.
constexpr double kQuaternionNormTolerance = 1e-2;

void requireIncreasing(double stamp, const std::vector<double>& stamps, const std::string& path,
                       std::size_t line) {
  if (!stamps.empty() && !(stamp > stamps.back())) {
    // the shortest text that reads back as each value (0.1, never 0.10000000000000001)
    throw InputError(where(path, line) + ": time stamp " + formatNumber(stamp) +
                     " is not after the one before (" + formatNumber(stamps.back()) +
                     "); stamps must increase strictly");
  }
}

Eigen::Isometry3d kittiPose(const std::vector<std::string_view>& tokens, const std::string& path,
                            std::size_t line) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (int i = 0; i < 12; ++i) m(i / 4, i % 4) = number(tokens[i], path, line);
  try {
    checkRigidTransform(m, where(path, line));
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  Eigen::Isometry3d pose;
  pose.matrix() = m;
  return pose;
}

Eigen::Isometry3d tumPose(const std::vector<std::string_view>& tokens, const std::string& path,
                          std::size_t line) {
  double v[8];
  for (int i = 0; i < 8; ++i) v[i] = number(tokens[i], path, line);
  const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
  const double norm = q.norm();
  if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance)) {
    std::ostringstream os;
    os.precision(6);
    os << where(path, line) << ": quaternion (qx qy qz qw) = (" << v[4] << " " << v[5] << " "
       << v[6] << " " << v[7] << ") has norm " << norm << ", not 1 (tolerance "
       << kQuaternionNormTolerance << ")";
    throw InputError(os.str());
  }
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = q.normalized().toRotationMatrix();
  m.topRightCorner<3, 1>() = Eigen::Vector3d(v[1], v[2], v[3]);
  try {
    checkRigidTransform(m, where(path, line));  // the translation's bound
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  Eigen::Isometry3d pose;
  pose.matrix() = m;
  return pose;
}

std::size_t columns(TrajectoryFormat format) { return format == TrajectoryFormat::Kitti ? 12 : 8; }

}  // namespace

TrajectoryFormat parseTrajectoryFormat(const std::string& name) {
  if (name == "auto") return TrajectoryFormat::Auto;
  if (name == "kitti") return TrajectoryFormat::Kitti;
  if (name == "tum") return TrajectoryFormat::Tum;
  throw std::invalid_argument("trajectory format must be auto, kitti or tum, got '" +
                              quoteForMessage(name) + "'");
}

const char* trajectoryFormatName(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::Kitti:
      return "kitti";
    case TrajectoryFormat::Tum:
      return "tum";
    default:
      return "auto";
  }
}

Trajectory readTrajectoryFile(const std::string& path, TrajectoryFormat format,
                              TrajectoryFormat* detected) {
  // The shortest pose line: TUM's "0 0 0 0 0 0 0 1\n", 16 bytes.
  const std::string text = readBoundedText(path, 16, sizeof(Eigen::Isometry3d) + sizeof(double));
  Trajectory trajectory;
  forEachDataLine(text, [&](std::size_t n, const std::vector<std::string_view>& tokens) {
    if (format == TrajectoryFormat::Auto) {
      if (tokens.size() == 12) {
        format = TrajectoryFormat::Kitti;
      } else if (tokens.size() == 8) {
        format = TrajectoryFormat::Tum;
      } else {
        throw InputError(where(path, n) + " has " + std::to_string(tokens.size()) +
                         " values: neither KITTI form (12: row-major 3x4 [R|t]) nor TUM form "
                         "(8: stamp tx ty tz qx qy qz qw)");
      }
    }
    if (tokens.size() != columns(format)) {
      throw InputError(where(path, n) + " has " + std::to_string(tokens.size()) + " values, not " +
                       std::to_string(columns(format)) + " (" +
                       (format == TrajectoryFormat::Kitti
                            ? "KITTI form: row-major 3x4 [R|t]"
                            : "TUM form: stamp tx ty tz qx qy qz qw") +
                       ")");
    }
    if (format == TrajectoryFormat::Kitti) {
      trajectory.poses.push_back(kittiPose(tokens, path, n));
    } else {
      Eigen::Isometry3d pose = tumPose(tokens, path, n);
      const double stamp = number(tokens[0], path, n);
      requireIncreasing(stamp, trajectory.stamps, path, n);
      trajectory.stamps.push_back(stamp);
      trajectory.poses.push_back(pose);
    }
  });
  if (trajectory.empty()) throw InputError(path + ": no poses (every line blank or a comment)");
  if (detected) *detected = format;
  return trajectory;
}

std::string formatKittiPoses(const std::vector<Eigen::Isometry3d>& poses) {
  std::string text;
  for (const Eigen::Isometry3d& pose : poses) {
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 4; ++col) {
        char num[32];
        std::snprintf(num, sizeof num, "%.9e", pose.matrix()(row, col));
        if (row || col) text += ' ';
        text += num;
      }
    }
    text += '\n';
  }
  return text;
}

namespace {

/// What the readers check of every pose (checkRigidTransform): a writer refuses what they would.
void requireReadable(const Trajectory& trajectory) {
  for (std::size_t i = 0; i < trajectory.size(); ++i)
    checkRigidTransform(trajectory.poses[i].matrix(), "pose " + std::to_string(i));
}

}  // namespace

std::string formatKittiTrajectory(const Trajectory& trajectory) {
  requireReadable(trajectory);
  return formatKittiPoses(trajectory.poses);
}

std::string formatTumTrajectory(const Trajectory& trajectory) {
  if (trajectory.hasStamps() && trajectory.stamps.size() != trajectory.poses.size()) {
    throw std::invalid_argument("TUM trajectory: " + std::to_string(trajectory.stamps.size()) +
                                " stamps for " + std::to_string(trajectory.poses.size()) +
                                " poses");
  }
  requireReadable(trajectory);
  std::string text;
  double previous = 0.0;
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Eigen::Isometry3d& pose = trajectory.poses[i];
    const double stamp = trajectory.hasStamps() ? trajectory.stamps[i] : static_cast<double>(i);
    Eigen::Quaterniond q(pose.linear());
    q.normalize();
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    const Eigen::Vector3d t = pose.translation();
    // %.9f of a stamp up to 1.8e308 takes 320 characters: the buffer holds every finite value.
    char line[512];
    std::snprintf(line, sizeof line, "%.9f %.9e %.9e %.9e %.9e %.9e %.9e %.9e\n", stamp, t.x(),
                  t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
    // The reader takes stamps that increase strictly as written (to 1e-9 s)
    const double written = std::strtod(line, nullptr);
    if (!std::isfinite(stamp) || (i > 0 && !(written > previous))) {
      throw std::invalid_argument(
          "TUM trajectory: stamp " + std::to_string(i) + " (" + formatNumber(stamp) + ") " +
          (std::isfinite(stamp)
               ? "is not after the one before (" + formatNumber(trajectory.stamps[i - 1]) +
                     ") as written to 1e-9 s; stamps must increase strictly"
               : "is not finite"));
    }
    previous = written;
    text += line;
  }
  return text;
}

std::vector<double> readStamps(const std::string& path) {
  // The shortest stamp line: "0\n", 2 bytes.
  const std::string text = readBoundedText(path, 2, sizeof(double));
  std::vector<double> stamps;
  forEachDataLine(text, [&](std::size_t n, const std::vector<std::string_view>& tokens) {
    if (tokens.size() != 1) {
      throw InputError(where(path, n) + " has " + std::to_string(tokens.size()) +
                       " values, not one time stamp");
    }
    const double stamp = number(tokens[0], path, n);
    requireIncreasing(stamp, stamps, path, n);
    stamps.push_back(stamp);
  });
  return stamps;
}

std::vector<Eigen::Isometry3d> readTumTrajectory(const std::string& path, std::size_t frames) {
  requireRegularFile(path);
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  std::vector<Eigen::Isometry3d> poses;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line) && poses.size() < frames; ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    std::istringstream is(line);
    double v[8];
    std::string token;
    for (double& x : v) {
      try {
        if (!(is >> token)) throw std::invalid_argument("too few numbers");
        x = parseFiniteDouble(token, "value");
      } catch (const std::invalid_argument&) {
        throw InputError(path + ": line " + std::to_string(n) +
                         " is not 'timestamp tx ty tz qx qy qz qw' (8 finite numbers)");
      }
    }
    if (is >> token) {
      throw InputError(path + ": line " + std::to_string(n) +
                       " has more than 8 numbers ('timestamp tx ty tz qx qy qz qw')");
    }
    Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    if (q.norm() < 1e-9)
      throw InputError(path + ": line " + std::to_string(n) + ": zero quaternion");
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = q.normalized().toRotationMatrix();
    t.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    poses.push_back(t);
  }
  if (poses.size() < frames) {
    throw InputError(path + ": " + std::to_string(poses.size()) + " pose(s) for " +
                     std::to_string(frames) + " frame(s)");
  }
  return poses;
}

}  // namespace metricmap
