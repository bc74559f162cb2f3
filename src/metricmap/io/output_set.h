#pragma once
/// \file output_set.h
/// \brief All-or-nothing commit of a command's several output files.

#include <string>
#include <utility>
#include <vector>

namespace metricmap {

/// \brief Refuse an output path that names a directory, a FIFO, a device or a socket: such a file
/// is never replaced by a regular one. \throws std::runtime_error naming the path
void checkOutputPath(const std::string& path);

/// \brief Stages outputs as temporaries next to their destinations and renames them all at once.
///
/// Each output is written to the path stage() returns (same directory, same extension); commit()
/// renames every staged file into place. If commit() is never reached (an exception, a failed
/// later output), the destructor removes every temporary, so nothing is left behind.
class OutputSet {
 public:
  OutputSet() = default;
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();

  /// \brief Check `path` (checkOutputPath, its directory exists) and return the temporary to write.
  /// \throws std::runtime_error naming the path
  std::string stage(const std::string& path);

  /// \brief A directory of outputs: files are written into the returned temporary directory and
  /// moved into `path` (created if missing) on commit. \throws std::runtime_error naming the path
  std::string stageDirectory(const std::string& path);

  /// \brief Rename every staged output into place. \throws std::runtime_error naming the path
  void commit();

 private:
  struct Staged {
    std::string temporary, destination;
    bool directory = false;
  };
  std::vector<Staged> staged_;
};

}  // namespace metricmap
