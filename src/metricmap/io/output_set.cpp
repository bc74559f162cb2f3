#include "metricmap/io/output_set.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "metricmap/io/atomic_file.h"
#include "metricmap/io/file_identity.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

void checkParent(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty() && !fs::is_directory(parent, ec))
    throw std::runtime_error(path + ": cannot write (no such directory '" + parent.string() + "')");
}

}  // namespace

void checkOutputPath(const std::string& path) {
  if (path.empty()) throw std::runtime_error("empty output file name");
  if (path.back() == '/') throw std::runtime_error(path + ": is a directory, not a file name");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw std::runtime_error(path + ": exists and is not a regular file (" +
                             (S_ISDIR(st.st_mode)                          ? "a directory"
                              : S_ISFIFO(st.st_mode)                       ? "a FIFO"
                              : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                           : "a special file") +
                             "); refusing to replace it");
  }
}

OutputSet::~OutputSet() {
  std::error_code ec;
  for (const Staged& s : staged_) {
    fs::remove_all(s.temporary, ec);
    forgetTemporary(s.temporary);
  }
}

std::string OutputSet::stage(const std::string& path) {
  checkOutputPath(path);
  checkParent(path);
  const FileIdentity id = fileIdentity(path);
  for (const Staged& s : staged_) {
    if (s.destination == path || sameFile(id, fileIdentity(s.destination)))
      throw std::runtime_error(path + ": named for two outputs (also as '" + s.destination + "')");
  }
  staged_.push_back({temporaryPathFor(path), path, false});
  return staged_.back().temporary;
}

std::string OutputSet::stageDirectory(const std::string& path) {
  std::error_code ec;
  const bool exists = fs::exists(path, ec);
  if (exists && !fs::is_directory(path, ec))
    throw std::runtime_error(path + ": exists and is not a directory");
  removeStaleTemporaries(path);  // what a killed run left
  std::string tmp;
  if (exists) {
    tmp = (fs::path(path) / (".tmp-" + std::to_string(::getpid()))).string();
  } else {
    std::string trimmed = path;
    while (trimmed.size() > 1 && trimmed.back() == '/') trimmed.pop_back();
    checkParent(trimmed);
    tmp = trimmed + ".tmp-" + std::to_string(::getpid());
  }
  if (!fs::create_directory(tmp, ec) || ec)
    throw std::runtime_error(path + ": cannot create a directory here (" + ec.message() + ")");
  registerTemporary(tmp, /*directory=*/true);
  staged_.push_back({tmp, path, true});
  return tmp;
}

void OutputSet::commit() {
  // Check every destination again: something may have appeared since stage().
  for (const Staged& s : staged_) {
    if (!s.directory) checkOutputPath(s.destination);
  }
  std::error_code ec;
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    const Staged& s = staged_[i];
    if (!s.directory) {
      if (std::rename(s.temporary.c_str(), s.destination.c_str()) != 0)
        throw std::runtime_error(s.destination + ": cannot write (" + std::strerror(errno) + ")");
      forgetTemporary(s.temporary);
      continue;
    }
    if (!fs::exists(s.destination, ec)) {
      fs::rename(s.temporary, s.destination, ec);
      if (ec) throw std::runtime_error(s.destination + ": cannot write (" + ec.message() + ")");
      forgetTemporary(s.temporary);
      continue;
    }
    for (const fs::directory_entry& e : fs::directory_iterator(s.temporary, ec)) {
      const fs::path to = fs::path(s.destination) / e.path().filename();
      checkOutputPath(to.string());
      fs::rename(e.path(), to, ec);
      if (ec) throw std::runtime_error(to.string() + ": cannot write (" + ec.message() + ")");
    }
    fs::remove_all(s.temporary, ec);
    forgetTemporary(s.temporary);
  }
  staged_.clear();
}

}  // namespace metricmap
