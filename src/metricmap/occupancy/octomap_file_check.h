#pragma once
/// \file octomap_file_check.h
/// \brief Structural check of OctoMap .bt/.ot bytes before liboctomap parses them (its readers
/// trust the file: a truncated or hostile tree makes them read garbage or recurse unbounded).

#include <cstddef>
#include <string>

namespace metricmap {

/// \brief The voxel edges (m) an OctoMap file's `res` line may hold for metricmap's reader: 0.1 mm
/// (below that the 16-level key space is under 7 m wide) to 1 km. Options whose value ends up in
/// that line are checked against the same range.
constexpr double kOctomapMinResolution = 1e-4, kOctomapMaxResolution = 1e3;

/// \brief The header fields of an OctoMap file and where its tree data starts.
struct OctomapFileInfo {
  bool binary = false;   ///< .bt (2 bits per child) or .ot (float + child mask per node)
  std::string id;        ///< tree type, e.g. OcTree
  std::size_t size = 0;  ///< nodes announced in the header
  double resolution = 0.0;
  std::size_t data_offset = 0;  ///< first byte after the "data" line
  std::size_t nodes = 0;        ///< nodes found when walking the data
  std::size_t leaves = 0;       ///< nodes without children
};

/// \brief Parse the header and walk the whole tree (depth <= 16, every byte accounted for,
/// finite log-odds, node count equal to the header's size).
/// \param name the file name used in messages
/// \throws InputError "<name>: ..." on the first problem
OctomapFileInfo checkOctomapBytes(const std::string& bytes, const std::string& name);

}  // namespace metricmap
