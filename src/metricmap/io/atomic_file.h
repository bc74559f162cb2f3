#pragma once
/// \file atomic_file.h
/// \brief "Write to a temporary file, then rename": every writer's way of leaving either the
/// whole file at its destination or nothing.

#include <string>

namespace metricmap {

/// \brief The name to write `path` under before commitTemporary: same directory and
/// extension, ".tmp-PID-N" before the extension (dir/name.tmp-PID-N.ext), unique per call.
std::string temporaryPathFor(const std::string& path);

/// \brief checkOutputPath(path), then rename `temporary` to `path`. On any failure the
/// temporary is removed and std::runtime_error names `path` (as outputDisplayName shows it)
/// and the reason.
void commitTemporary(const std::string& temporary, const std::string& path);

/// \brief Remove a temporary after a failed write (no error if it does not exist).
void discardTemporary(const std::string& temporary);

}  // namespace metricmap
