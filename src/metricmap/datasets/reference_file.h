#pragma once
/// \file reference_file.h
/// \brief Reference trajectories and stamps beside a sequence's scans: the trajectory readers
/// (io/trajectory.h) with the count the sequence needs.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "metricmap/common/trajectory.h"

namespace metricmap {

/// \brief readStampsFile's count for "as many as the file has".
constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();

/// \brief A pose file of exactly `count` poses: KITTI rows (12 numbers) or TUM rows (8: stamp
/// tx ty tz qx qy qz qw, whose stamps are kept), told from the first data line.
/// \throws InputError naming the file: another length, malformed rows
Trajectory readReferencePoses(const std::string& path, std::size_t count);

/// \brief A stamps file of exactly `count` (or kAnyCount) strictly increasing finite numbers.
/// \throws InputError naming the file and line
std::vector<double> readStampsFile(const std::string& path, std::size_t count);

}  // namespace metricmap
