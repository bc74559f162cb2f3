#include "metricmap/io/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

std::uint64_t regularFileSize(const std::string& path) {
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
  return static_cast<std::uint64_t>(st.st_size);
}

}  // namespace

void requireRegularFile(const std::string& path) { regularFileSize(path); }

std::ifstream openRegularFile(const std::string& path, std::ios::openmode mode) {
  requireRegularFile(path);
  std::ifstream in(path, mode);
  if (!in) throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  return in;
}

std::string readRegularFile(const std::string& path, std::uint64_t max_bytes) {
  const std::uint64_t size = regularFileSize(path);
  if (size > max_bytes) {
    throw CapacityError(path + ": " + std::to_string(size) + " bytes, more than the " +
                        std::to_string(max_bytes) + " this reader takes");
  }
  checkMemory(size, 1, path + " (" + std::to_string(size) + " bytes)");
  std::ifstream in = openRegularFile(path);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (in.bad()) throw InputError(path + ": read error");
  bytes.resize(static_cast<std::size_t>(in.gcount()));  // the file may have shrunk since
  return bytes;
}

}  // namespace metricmap
