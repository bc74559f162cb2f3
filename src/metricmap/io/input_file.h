#pragma once
/// \file input_file.h
/// \brief Input paths must name regular files: opening a FIFO blocks, a directory or device
/// reads as garbage.

#include <string>

namespace metricmap {

/// \brief \throws InputError "PATH: cannot open (...)" unless `path` is an existing regular file
/// (symbolic links followed).
void requireRegularFile(const std::string& path);

}  // namespace metricmap
