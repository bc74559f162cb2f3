#include "metricmap/io/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "metricmap/exceptions.h"

namespace metricmap {

void requireRegularFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) {
    throw InputError(path + ": cannot open (not a regular file: " +
                     (S_ISDIR(st.st_mode)    ? "a directory"
                      : S_ISFIFO(st.st_mode) ? "a FIFO"
                                             : "a device or special file") +
                     ")");
  }
}

}  // namespace metricmap
