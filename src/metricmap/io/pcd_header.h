#pragma once
/// \file pcd_header.h
/// \brief Checks a PCD file's header against its size before pcl::io reads it.
///
/// pcl::PCDReader trusts the header: an absurd POINTS allocates that much memory, and an ascii
/// body with garbage numbers silently reads as zeros. These checks refuse such files with a
/// message naming the file and the problem.

#include <cstdint>
#include <string>
#include <vector>

namespace metricmap {

/// \brief The parts of a PCD header the checks need.
struct PcdHeader {
  std::vector<std::string> fields;
  std::vector<int> sizes;
  std::vector<char> types;
  std::vector<int> counts;
  std::uint64_t width = 0, height = 0, points = 0;
  std::string data;               ///< ascii, binary or binary_compressed
  std::uint64_t data_offset = 0;  ///< byte offset of the body
  std::uint64_t point_bytes = 0;  ///< bytes of one point in binary
  std::uint64_t values_per_point = 0;
  std::string ascii_body;      ///< ascii only: the well-formed point lines (at most `points`)
  bool has_viewpoint = false;  ///< a VIEWPOINT line was present
  /// WIDTH 0 HEIGHT 0 with POINTS n > 0 (written by real pipelines; Open3D reads it, PCL does
  /// not): read as an unorganised cloud, width n, height 1
  bool zero_dimensions = false;
  double viewpoint[7] = {0, 0, 0, 1, 0, 0, 0};  ///< tx ty tz qw qx qy qz
};

/// \brief Parse and check the header of `path`; for binary bodies check sizes, for
/// binary_compressed the compressed block; for ascii pre-scan the body and keep its
/// well-formed lines (pcl::PCDReader reads a malformed line as a point of zeros and drops the
/// last real point instead, so the reader feeds it the kept lines).
/// \param[out] skipped_lines ascii lines with the wrong number of values (skipped by PCL)
/// \throws InputError with a one-line message naming the file
/// \brief A token PCL's ascii decoders (PCD and PLY) read as we do: "nan"/"inf" (any case,
/// signed inf), or a finite decimal number within float range (PCL falls back to atof and casts:
/// hex would read as 0, 1e39 as an out-of-range float cast).
bool isAsciiValue(const std::string& s);

PcdHeader checkPcdFile(const std::string& path, std::uint64_t& skipped_lines);

}  // namespace metricmap
