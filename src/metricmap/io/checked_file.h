#pragma once
/// \file checked_file.h
/// \brief A file written with every write and the final close checked (a full disk shows at
/// either), errors naming the destination the caller reports, not a temporary.

#include <string>
#include <string_view>

namespace metricmap {

/// \brief `path` as a message should name it: an OutputSet or atomic-write temporary
/// ("dir/name.tmp-PID-N.ext", "name.ext.tmp-PID-N") is shown as its destination.
std::string outputDisplayName(const std::string& path);

/// \brief Writes one new file (created or truncated). \throws std::runtime_error
/// "NAME: cannot write (REASON)" on any failed write or close, NAME from outputDisplayName.
class CheckedFile {
 public:
  explicit CheckedFile(const std::string& path);
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;
  /// Closes without a check if close() was not reached (an exception is on its way).
  ~CheckedFile();

  /// \brief Append bytes (buffered; the buffer is written out when it fills).
  void write(std::string_view bytes);
  /// \brief Write what is buffered and close; every failure throws.
  void close();

 private:
  void flush();
  void writeAll(const char* p, std::size_t n);
  [[noreturn]] void fail(int err) const;

  std::string path_;
  std::string buffer_;
  int fd_ = -1;
};

}  // namespace metricmap
