#pragma once
/// \file reference_file.h
/// \brief Reference trajectories and stamps beside a sequence's scans.

#include <cstddef>
#include <string>
#include <vector>

#include "metricmap/evaluation/trajectory.h"

namespace metricmap {

/// \brief A pose file of exactly `count` poses: KITTI rows (12 numbers) or TUM rows (8: stamp
/// tx ty tz qx qy qz qw, whose stamps are kept), told from the first data line.
/// \throws InputError naming the file: another length, malformed rows
Trajectory readReferencePoses(const std::string& path, std::size_t count);

/// \brief A stamps file of exactly `count` strictly increasing finite numbers, one per line.
/// \throws InputError naming the file and line
std::vector<double> readStampsFile(const std::string& path, std::size_t count);

/// \brief Non-blank lines that do not start with '#'.
std::size_t countDataLines(const std::string& path);

}  // namespace metricmap
