#pragma once
// Files written by a test binary in one directory, removed when it exits; the message of the
// InputError a call throws.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "metricmap/exceptions.h"

namespace metricmap::test_support {

struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(const std::string& prefix)
      : path(std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  /// Write `text` to NAME in the directory; its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path p = path / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
};

/// The message of the InputError f() throws, "(no InputError)" when it throws none.
template <typename F>
std::string inputErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace metricmap::test_support
