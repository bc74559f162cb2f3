#pragma once
/// \file load_report.h
/// \brief What a reader found in a file besides the points.

#include <cstdint>
#include <string>
#include <vector>

namespace metricmap {

/// \brief Facts about a loaded file, for `metricmap info` and for warnings.
struct LoadReport {
  std::string path;
  std::string format;  ///< "pcd ascii", "pcd binary", "pcd binary_compressed", "ply", "kitti bin"
  std::vector<std::string> fields;  ///< field names in the file
  std::uint32_t width = 0;          ///< as stored (organized clouds have height > 1)
  std::uint32_t height = 0;
  std::uint64_t points_in_file = 0;             ///< before NaN/Inf removal
  std::uint64_t nonfinite_dropped = 0;          ///< points with a NaN/Inf coordinate, removed
  std::uint64_t skipped_lines = 0;              ///< malformed lines skipped in an ascii body
  std::vector<std::string> warnings;            ///< one line each, naming the file
  bool has_viewpoint = false;                   ///< PCD VIEWPOINT line present (sensor pose)
  double viewpoint[7] = {0, 0, 0, 1, 0, 0, 0};  ///< tx ty tz qw qx qy qz as in the file
};

}  // namespace metricmap
