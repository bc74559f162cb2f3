#include "metricmap/io/carmen_log.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "metricmap/common/parse_number.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

bool number(std::string_view s, double& v) {
  try {
    v = parseFiniteDouble(s, "log value");
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

/// An integer count in [min, available] (the tokens left on the line): never a cast of a
/// double that may not fit.
bool count(std::string_view s, std::size_t min, std::size_t available, std::size_t& n) {
  if (available < min) return false;
  try {
    n = static_cast<std::size_t>(
        parseInteger(s, "count", static_cast<long long>(min), static_cast<long long>(available)));
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

/// "stamp host logger_stamp" at t[first]: two numbers around a host name that is not one (a
/// number there means the beam count and the ranges disagree).
bool stampHostStamp(const std::vector<std::string_view>& t, std::size_t first, double& stamp) {
  double host = 0.0, logger = 0.0;
  return number(t[first], stamp) && !number(t[first + 1], host) && number(t[first + 2], logger);
}

bool pose(const std::vector<std::string_view>& t, std::size_t first, Pose2D& p) {
  return number(t[first], p.x) && number(t[first + 1], p.y) && number(t[first + 2], p.theta);
}

/// Ranges t[first, first + n): beam k at start + k step; valid when 0 < r <= max_range.
bool ranges(const std::vector<std::string_view>& t, std::size_t first, std::size_t n, double start,
            double step, double max_range, LaserScan& scan) {
  scan.angles.resize(n);
  scan.ranges.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    double r = 0.0;
    if (!number(t[first + k], r)) return false;
    scan.angles[k] = start + step * static_cast<double>(k);
    scan.ranges[k] = (r > 0.0 && r <= max_range && r <= kMaxLaserRange) ? r : kNaN;
  }
  return true;
}

bool parseFlaser(const std::vector<std::string_view>& t, CarmenLaser& out) {
  std::size_t n = 0;
  if (t.size() < 2 || !count(t[1], 1, t.size() - 2, n)) return false;
  const double step =
      (n % 2 == 1 && n > 1) ? M_PI / static_cast<double>(n - 1) : M_PI / static_cast<double>(n);
  if (!ranges(t, 2, n, -M_PI / 2, step, INFINITY, out.scan)) return false;
  // What follows the n ranges tells whether n counts them: nothing (the oldest form), the two
  // poses, or the poses, stamp, host and logger stamp. Any other count of tokens (a count one
  // above or below the ranges given, a cut or run-on line) is malformed, never ranges and poses
  // shifted by one.
  const std::size_t rest = t.size() - 2 - n, tail = 2 + n;
  if (rest == 0) return true;  // oldest form: ranges only
  if (rest != 6 && rest != 9) return false;
  Pose2D laser, odom;
  if (!pose(t, tail, laser) || !pose(t, tail + 3, odom)) return false;
  out.laser_pose = laser;
  out.odometry = odom;
  return rest == 6 || stampHostStamp(t, tail + 6, out.stamp);
}

bool parseRobotLaser(const std::vector<std::string_view>& t, CarmenLaser& out) {
  double start = 0, fov = 0, res = 0, max_r = 0;
  std::size_t n = 0;
  if (t.size() < 9 || !number(t[2], start) || !number(t[3], fov) || !number(t[4], res) ||
      !number(t[5], max_r) || !count(t[8], 1, t.size() - 9, n) || !(res > 0.0)) {
    return false;
  }
  // A maximum range reading is no return (1e-9 below it: the logged value equals it).
  if (!ranges(t, 9, n, start, res, max_r > 0.0 ? max_r * (1 - 1e-9) : INFINITY, out.scan))
    return false;
  std::size_t k = 9 + n;
  if (k == t.size()) return true;  // ranges only
  std::size_t m = 0;
  if (!count(t[k], 0, t.size() - k - 1, m)) return false;
  k += 1 + m;  // remissions: not kept
  // As FLASER: nothing, the two poses, the poses and tv rv forward_safety side_safety
  // turn_axis, or those and stamp, host and logger stamp; any other tail is malformed.
  const std::size_t rest = t.size() - k;
  if (rest == 0) return true;
  if (rest != 6 && rest != 11 && rest != 14) return false;
  Pose2D laser, robot;
  if (!pose(t, k, laser) || !pose(t, k + 3, robot)) return false;
  out.laser_pose = laser;
  out.odometry = robot;
  if (rest == 11) {
    double v = 0.0;
    for (std::size_t i = k + 6; i < k + 11; ++i) {
      if (!number(t[i], v)) return false;
    }
  }
  return rest < 14 || stampHostStamp(t, k + 11, out.stamp);
}

}  // namespace

void splitTokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  constexpr std::string_view kBlanks = " \t\r\v\f";
  std::size_t i = line.find_first_not_of(kBlanks);
  while (i != std::string_view::npos) {
    const std::size_t j = line.find_first_of(kBlanks, i);
    tokens.push_back(line.substr(i, j == std::string_view::npos ? line.size() - i : j - i));
    if (j == std::string_view::npos) break;
    i = line.find_first_not_of(kBlanks, j);
  }
}

CarmenLineKind parseCarmenLine(const std::vector<std::string_view>& t, CarmenLaser& out) {
  if (t.empty()) return CarmenLineKind::Other;
  out.scan = LaserScan{};
  out.stamp = kNaN;
  out.odometry.reset();
  out.laser_pose.reset();
  if (t[0] == "FLASER") {
    out.robot_laser = false;
    return parseFlaser(t, out) ? CarmenLineKind::Laser : CarmenLineKind::Malformed;
  }
  if (t[0] == "ROBOTLASER1") {
    out.robot_laser = true;
    return parseRobotLaser(t, out) ? CarmenLineKind::Laser : CarmenLineKind::Malformed;
  }
  return t[0] == "ODOM" ? CarmenLineKind::Odometry : CarmenLineKind::Other;
}

void CarmenLogReader::checkPoseAngles(const CarmenLaser& out) const {
  // A heading beyond ±kMaxAngle is a number a double no longer resolves to a turn (its
  // spacing at 1e17 is 16 rad): the line is refused, never read as some other heading.
  for (const auto& [what, pose] :
       {std::pair{"laser pose", out.laser_pose}, std::pair{"odometry pose", out.odometry}}) {
    if (pose && std::fabs(pose->theta) > kMaxAngle) {
      std::ostringstream msg;
      msg << path() << ": line " << out.line << ": " << what << " heading " << pose->theta
          << " rad is beyond +-" << kMaxAngle << " rad";
      throw InputError(msg.str());
    }
  }
}

CarmenLogReader::CarmenLogReader(const std::string& path, const TextLimits& limits)
    : lines_(path, limits) {}

bool CarmenLogReader::next(CarmenLaser& out) {
  while (lines_.next(line_)) {
    splitTokens(line_, tokens_);
    switch (parseCarmenLine(tokens_, out)) {
      case CarmenLineKind::Laser:
        out.line = lines_.lineNumber();
        checkPoseAngles(out);
        return true;
      case CarmenLineKind::Malformed:
        ++skipped_;
        break;
      case CarmenLineKind::Odometry:
        ++odometry_;
        break;
      case CarmenLineKind::Other:
        break;
    }
  }
  return false;
}

void CarmenLogReader::skipTo(std::size_t line) {
  while (lines_.lineNumber() + 1 < line && lines_.next(line_)) {
  }
}

}  // namespace metricmap
