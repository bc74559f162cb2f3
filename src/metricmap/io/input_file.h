#pragma once
/// \file input_file.h
/// \brief Input paths must name regular files: opening a FIFO blocks, a directory or device
/// reads as garbage (/dev/zero never ends).

#include <cstdint>
#include <fstream>
#include <string>

namespace metricmap {

/// \brief \throws InputError "PATH: cannot open (...)" unless `path` is an existing regular file
/// (symbolic links followed).
void requireRegularFile(const std::string& path);

/// \brief requireRegularFile, then open it for reading. \throws InputError naming the path
std::ifstream openRegularFile(const std::string& path,
                              std::ios::openmode mode = std::ios::in | std::ios::binary);

/// \brief The whole of a regular file, at most `max_bytes` (checked against its size before
/// anything is read; the read stops at the size the file had when it was checked).
/// \throws InputError naming the path; CapacityError naming the path when it is larger
std::string readRegularFile(const std::string& path, std::uint64_t max_bytes);

}  // namespace metricmap
