#pragma once
/// \file atomic_file.h
/// \brief "Write to a temporary file, then rename": every writer's way of leaving either the
/// whole file at its destination or nothing.
///
/// Every temporary is registered while it lives. SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE,
/// SIGXCPU, SIGXFSZ and SIGABRT (those whose action was the default when the first temporary
/// was made) remove the registered temporaries in an async-signal-safe handler (unlink from a
/// preallocated table), then end the process by the same signal with its default action; so
/// does a call to exit(). A run killed by SIGKILL cannot clean up: the next run that writes an
/// output next to such a stale temporary removes it when the process that made it is gone.

#include <string>

namespace metricmap {

/// \brief The name to write `path` under before commitTemporary: same directory and
/// extension, ".tmp-PID-N" before the extension (dir/name.tmp-PID-N.ext), unique per call.
/// The name is registered for removal on a fatal signal, and stale temporaries of `path` left by
/// dead processes (removeStaleTemporaries) are removed first.
std::string temporaryPathFor(const std::string& path);

/// \brief checkOutputPath(path), then rename `temporary` to `path`. On any failure the
/// temporary is removed and std::runtime_error names `path` (as outputDisplayName shows it)
/// and the reason.
void commitTemporary(const std::string& temporary, const std::string& path);

/// \brief Remove a temporary after a failed write (no error if it does not exist).
void discardTemporary(const std::string& temporary);

/// \brief Register a temporary file (`directory` false) or a temporary directory and its files
/// (true) for removal on a fatal signal or exit(). temporaryPathFor registers its names itself.
void registerTemporary(const std::string& path, bool directory = false);

/// \brief Forget a registered temporary: it was renamed into place or removed.
void forgetTemporary(const std::string& path);

/// \brief Remove the temporaries of `path` (`dir/name.tmp-PID-N[...].ext`, and for a directory
/// output `name.tmp-PID` and `name/.tmp-PID`) whose process PID no longer exists: what a run
/// killed by SIGKILL left. Temporaries of live processes are left alone. Each directory is
/// listed once per process.
/// \return how many were removed
std::size_t removeStaleTemporaries(const std::string& path);

}  // namespace metricmap
