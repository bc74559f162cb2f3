#pragma once
/// \file carmen_source.h
/// \brief A CARMEN laser log (.clf/.log, plain, gzip or bzip2) as a ScanSource: one scan per
/// FLASER or ROBOTLASER1 line, with its stamp (ipc_timestamp) and the raw odometry the line
/// carries (FLASER odom_x odom_y odom_theta; ROBOTLASER1 robot pose). ODOM lines are counted,
/// not interpolated: a scan's odometry is its own line's, as the SLAM benchmark's tools take it.
///
/// Opening reads the log once (to count the scans and keep each one's line and stamp: 16 bytes
/// per scan); scan(i) reads forward from the last scan read and reads the log again from its
/// start to go back (about 1.5 s for the 2.3 MB intel.clf.bz2).
///
/// Stamps: every scan's stamp when every scan line has one (SourceInfo::stamps), else none.
/// They are finite but need not increase: raw logs stamp scans when IPC delivers them, and the
/// Intel Research Lab log steps back 631 times (by up to 0.9 s).
///
/// Frames: points are in the laser frame (beam k at angle a_k: x = r cos a_k, y = r sin a_k,
/// z = 0; NaN for a beam without return). The odometry is base -> odometry world (yaw = theta).
/// SourceInfo::sensor_to_base is the laser's offset on the robot when every scan is a
/// ROBOTLASER1 line (robot_pose^-1 * laser_pose of the first), else the identity: FLASER lines
/// give no offset (their x y theta is the laser pose, equal to the odometry in raw logs).

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "metricmap/datasets/scan_source.h"

namespace metricmap {

class CarmenLogReader;

/// \brief Scans of a CARMEN log. Not thread-safe.
class CarmenSource : public ScanSource {
 public:
  /// \brief Open and count the log.
  /// \throws InputError naming the file when it cannot be read, is damaged or has no scan
  /// \throws CapacityError when its scan index does not fit in the memory budget
  explicit CarmenSource(const std::string& path);
  ~CarmenSource() override;

  std::size_t size() const override { return lines_.size(); }
  /// \brief Scan i; `name` is "PATH: line N". \throws InputError naming the log when i >= size()
  /// \throws InputError naming the file when it cannot be read again or has changed
  Scan scan(std::size_t i) override;
  const SourceInfo& info() const override { return info_; }

  /// \brief FLASER/ROBOTLASER1 lines skipped as malformed.
  std::size_t skippedLines() const { return skipped_lines_; }
  /// \brief ODOM lines in the log.
  std::size_t odometryLines() const { return odometry_lines_; }
  /// \brief One line per thing the caller should know (skipped lines, missing stamps).
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  SourceInfo info_;
  std::vector<std::size_t> lines_;  ///< line of scan i
  std::unique_ptr<CarmenLogReader> reader_;
  std::size_t next_ = 0;  ///< index of the scan reader_ reads next
  std::size_t skipped_lines_ = 0, odometry_lines_ = 0;
  std::vector<std::string> warnings_;
};

/// \brief Open a CARMEN log as a source (a CarmenSource).
/// \throws InputError naming the file when it cannot be read, is damaged or has no scan
std::unique_ptr<ScanSource> openCarmenSource(const std::string& path);

}  // namespace metricmap
