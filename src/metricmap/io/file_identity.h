#pragma once
/// \file file_identity.h
/// \brief Which file a path names, compared by identity rather than spelling: `a.pcd`,
/// `./a.pcd`, `$PWD/a.pcd`, `sub/../a.pcd`, a symbolic link to it and a hard link to it are one
/// file. Used to refuse an output that would replace an input or another output of the same run.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace metricmap {

/// \brief What identifies a file: device and inode when the path names an existing file
/// (symbolic links followed), else its normalised absolute path.
struct FileIdentity {
  bool exists = false;          ///< stat() succeeded: device and inode are set
  std::uint64_t device = 0;     ///< st_dev
  std::uint64_t inode = 0;      ///< st_ino
  std::string normalised_path;  ///< when it does not exist: absolute, lexically normal, symlinked
                                ///< parent directories resolved
};

/// \brief The identity of `path` (never throws for a missing or unreadable path: such a path is
/// identified by its normalised absolute form).
FileIdentity fileIdentity(const std::string& path);

/// \brief True when both name one file: the same device and inode when both exist, the same
/// normalised path when neither does (an existing file and a missing one are never the same).
bool sameFile(const FileIdentity& a, const FileIdentity& b);

/// \brief A path with the role it plays in a command (an option such as "--out", or a
/// description such as "input" or "poses file").
using RolePath = std::pair<std::string, std::string>;

/// \brief Two roles that name one file: two outputs, or an output and an input.
struct FileClash {
  RolePath first;   ///< an output, or the input when `output_is_input`
  RolePath second;  ///< the output that names the same file
  bool output_is_input = false;
};

/// \brief The first clash among `outputs` (each against the others) and between each output and
/// every input; nothing when all outputs name distinct files that are not inputs. Empty paths
/// are skipped. Two inputs naming one file are not a clash. Inputs are compared through a hash
/// of their identities, so thousands of inputs (a KITTI sequence's scans) cost one stat each.
std::optional<FileClash> findFileClash(const std::vector<RolePath>& inputs,
                                       const std::vector<RolePath>& outputs);

/// \brief The first two `inputs` that name one existing file however spelled (`a.pcd` and
/// `./a.pcd`, a link to it), in the order given: `first` is the earlier. Nothing when every
/// existing input is a distinct file; paths that do not exist and empty paths are skipped (their
/// readers report them). One stat per input.
std::optional<std::pair<RolePath, RolePath>> findRepeatedInput(const std::vector<RolePath>& inputs);

}  // namespace metricmap
