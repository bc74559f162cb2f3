#pragma once
/// \file carmen_log.h
/// \brief CARMEN laser logs (.clf/.log, plain or gzip/bzip2) message by message: FLASER and
/// ROBOTLASER1 scans with their time stamps and raw odometry, ODOM lines counted.
///
/// Formats (one message per line, tokens separated by blanks, every message ending with
/// `ipc_timestamp ipc_hostname logger_timestamp`):
/// - `FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp host logger_timestamp`:
///   n ranges (m) over 180 degrees from -90 (step pi/(n-1) for an odd n such as 181 or 361, else
///   pi/n); x y theta is the laser's pose, odom_x odom_y odom_theta the robot's raw odometry.
///   Old logs end after the six pose numbers (no stamp) or after the ranges (neither).
/// - `ROBOTLASER1 laser_type start_angle fov resolution max_range accuracy remission_mode n
///   r1..rn m v1..vm laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv
///   forward_safety side_safety turn_axis ipc_timestamp host logger_timestamp`: beam k at
///   start_angle + k resolution; ranges at or beyond max_range are no return.
/// - `ODOM x y theta tv rv accel ipc_timestamp host logger_timestamp`: counted, not used (a
///   scan's odometry is the one its own line carries, as the SLAM benchmark's tools take it).
///
/// A scan line whose ranges are not n numbers, or that is cut inside its pose fields, or whose
/// pose or stamp is not a finite number, is malformed: skipped and counted.

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "metricmap/common/pose_2d.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/text_stream.h"

namespace metricmap {

/// \brief One laser message of a CARMEN log.
struct CarmenLaser {
  /// \brief The beams (ranges NaN where there was no return).
  LaserScan scan;
  /// \brief 1-based line of the message in the (decompressed) text.
  std::size_t line = 0;
  /// \brief True for ROBOTLASER1, false for FLASER.
  bool robot_laser = false;
  /// \brief ipc_timestamp (s); NaN when the line has none (old logs).
  double stamp = std::numeric_limits<double>::quiet_NaN();
  /// \brief The robot's raw odometry (FLASER odom_x odom_y odom_theta; ROBOTLASER1 robot pose).
  std::optional<Pose2D> odometry;
  /// \brief The laser's pose (FLASER x y theta; ROBOTLASER1 laser pose).
  std::optional<Pose2D> laser_pose;
};

/// \brief What one line of a CARMEN log is.
enum class CarmenLineKind { Laser, Odometry, Malformed, Other };

/// \brief Parse one line (already split into tokens). `out` is filled for Laser (its `line` is
/// left alone). Never throws for bad content.
CarmenLineKind parseCarmenLine(const std::vector<std::string_view>& tokens, CarmenLaser& out);

/// \brief Reads a CARMEN log one laser message at a time (only the current line in memory).
/// Not thread-safe.
class CarmenLogReader {
 public:
  /// \throws InputError naming the path when it cannot be opened
  explicit CarmenLogReader(const std::string& path, const TextLimits& limits = {});

  /// \brief The next FLASER/ROBOTLASER1 message; other lines are counted or ignored.
  /// \return false at the end of the log
  /// \throws InputError naming the file (and line) when the text cannot be read, or a laser
  /// line's pose has a heading beyond ±kMaxAngle rad
  bool next(CarmenLaser& out);

  /// \brief Skip lines without parsing them, so that the next line read is `line` (1-based);
  /// nothing happens when the reader is already past it.
  void skipTo(std::size_t line);

  /// \brief Scan lines skipped as malformed so far.
  std::size_t skippedLines() const { return skipped_; }
  /// \brief ODOM lines seen so far.
  std::size_t odometryLines() const { return odometry_; }
  const std::string& path() const { return lines_.path(); }
  TextCompression compression() const { return lines_.compression(); }

 private:
  TextLineReader lines_;
  std::string line_;
  std::vector<std::string_view> tokens_;
  std::size_t skipped_ = 0;
  std::size_t odometry_ = 0;

  void checkPoseAngles(const CarmenLaser& out) const;
};

/// \brief Split a line at blanks (space, tab, CR, VT, FF).
void splitTokens(std::string_view line, std::vector<std::string_view>& tokens);

}  // namespace metricmap
