#include "metricmap/io/checked_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace metricmap {
namespace {

constexpr std::size_t kBufferBytes = 1 << 20;

/// Removes the first ".tmp-PID-N" of this process from `s`; false if there is none.
bool stripTag(std::string& s) {
  const std::string tag = ".tmp-" + std::to_string(::getpid()) + "-";
  const std::size_t at = s.find(tag);
  if (at == std::string::npos) return false;
  std::size_t end = at + tag.size();
  const std::size_t digits = end;
  while (end < s.size() && s[end] >= '0' && s[end] <= '9') ++end;
  if (end == digits) return false;
  s.erase(at, end - at);
  return true;
}

}  // namespace

std::string outputDisplayName(const std::string& path) {
  std::string name = path;
  while (stripTag(name)) {
  }
  return name;
}

CheckedFile::CheckedFile(const std::string& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) fail(errno);
  buffer_.reserve(kBufferBytes);
}

CheckedFile::~CheckedFile() {
  if (fd_ >= 0) ::close(fd_);
}

void CheckedFile::write(std::string_view bytes) {
  if (buffer_.size() + bytes.size() > kBufferBytes) flush();
  if (bytes.size() >= kBufferBytes) {
    writeAll(bytes.data(), bytes.size());  // large blocks go straight to the file
    return;
  }
  buffer_.append(bytes.data(), bytes.size());
}

void CheckedFile::writeAll(const char* p, std::size_t left) {
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? errno : ENOSPC);
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void CheckedFile::flush() {
  writeAll(buffer_.data(), buffer_.size());
  buffer_.clear();
}

void CheckedFile::close() {
  flush();
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail(errno);
}

void CheckedFile::fail(int err) const {
  throw std::runtime_error(outputDisplayName(path_) + ": cannot write (" + std::strerror(err) +
                           ")");
}

}  // namespace metricmap
