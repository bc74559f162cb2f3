#pragma once
/// \file trajectory.h
/// \brief Trajectory files: KITTI form (12 numbers per line: the row-major 3x4 [R|t] of
/// sensor -> world, no stamps) and TUM form ("stamp tx ty tz qx qy qz qw" per line), their
/// writers, and time-stamp files (one stamp per line, as KITTI's times.txt).

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/evaluation/trajectory.h"

namespace metricmap {

/// \brief The form of a trajectory file; Auto decides from the first data line (12 numbers:
/// KITTI, 8 numbers: TUM).
enum class TrajectoryFormat { Auto, Kitti, Tum };

/// \brief "auto" | "kitti" | "tum". \throws std::invalid_argument naming the text
TrajectoryFormat parseTrajectoryFormat(const std::string& name);

/// \brief "kitti" or "tum" (Auto: "auto").
const char* trajectoryFormatName(TrajectoryFormat format);

/// \brief A whole trajectory file in KITTI or TUM form.
///
/// Blank lines and lines whose first non-blank character is '#' are skipped. Every number goes
/// through parseFiniteDouble. KITTI rows must be rigid transforms (checkRigidTransform: rotation
/// orthonormal with det +1 to 1e-3, last row implied); a KITTI file gives a trajectory without
/// stamps. TUM quaternions must have a norm within 1e-2 of 1 (then normalised; a zero or
/// non-unit quaternion is refused) and the stamps must increase strictly. What is allocated is
/// bounded by the file's size (checked against the memory budget first).
/// \param path the file
/// \param format Kitti, Tum, or Auto (from the first data line's number count)
/// \param detected when not null, receives the form read (Kitti or Tum)
/// \throws InputError naming the file (and line): missing or not a regular file, no pose at
/// all, a line with the wrong count of numbers or a bad number, a bad rotation or quaternion,
/// stamps that do not increase; CapacityError when the file does not fit the memory budget
Trajectory readTrajectoryFile(const std::string& path,
                              TrajectoryFormat format = TrajectoryFormat::Auto,
                              TrajectoryFormat* detected = nullptr);

/// \brief The trajectory in KITTI form: the row-major 3x4 [R|t] of each pose, `%.9e`, one line
/// per pose; stamps are not written (KITTI keeps them in a separate times.txt).
std::string formatKittiTrajectory(const Trajectory& trajectory);

/// \brief The trajectory in TUM form, "stamp tx ty tz qx qy qz qw" per line (stamp `%.9f`,
/// the rest `%.9e`, quaternion normalised with qw >= 0). A trajectory without stamps is written
/// with its pose index (0, 1, 2, ...) as the stamp.
/// \throws std::invalid_argument when the trajectory has stamps but not one per pose, or stamps
/// that are not finite or (as written) not strictly increasing: what the reader would refuse
std::string formatTumTrajectory(const Trajectory& trajectory);

/// \brief A time-stamp file: one finite number per line (seconds), blank lines and '#'
/// comments skipped, strictly increasing. An empty file gives no stamps.
/// \throws InputError naming the file and line: a bad number, more than one number on a line, a
/// stamp not above the one before; CapacityError when the file does not fit the memory budget
std::vector<double> readStamps(const std::string& path);

/// \brief The first `frames` poses (sensor -> world) of a TUM trajectory; blank lines and
/// lines starting with '#' are skipped; frame k takes the k-th pose line.
/// \throws InputError naming the file and line for a malformed line, a zero quaternion or too
/// few poses
std::vector<Eigen::Isometry3d> readTumTrajectory(const std::string& path, std::size_t frames);

}  // namespace metricmap
