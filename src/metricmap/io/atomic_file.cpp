#include "metricmap/io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <unistd.h>

#include "metricmap/io/checked_file.h"
#include "metricmap/io/output_set.h"

namespace metricmap {

std::string temporaryPathFor(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const std::string tag = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) ||
      dot == (slash == std::string::npos ? 0 : slash + 1)) {
    return path + tag;
  }
  return path.substr(0, dot) + tag + path.substr(dot);
}

void discardTemporary(const std::string& temporary) { std::remove(temporary.c_str()); }

void commitTemporary(const std::string& temporary, const std::string& path) {
  try {
    checkOutputPath(path);
  } catch (...) {
    discardTemporary(temporary);
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int err = errno;
    discardTemporary(temporary);
    throw std::runtime_error(outputDisplayName(path) + ": cannot write (" + std::strerror(err) +
                             ")");
  }
}

}  // namespace metricmap
