#pragma once
/// \file text_stream.h
/// \brief Text files read line by line, plain or gzip/bzip2-compressed (told from the first
/// bytes, not the name), with bounded memory: a line longer than a limit is refused, and a
/// compressed file that expands beyond a ratio of its size (a decompression bomb) is refused.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace metricmap {

/// \brief How a file's bytes are stored.
enum class TextCompression { None, Gzip, Bzip2 };

/// \brief "plain", "gzip" or "bzip2".
const char* compressionName(TextCompression c);

/// \brief From the first bytes: 1f 8b -> Gzip, "BZh" -> Bzip2, anything else (also a file
/// shorter than that) -> None. \throws InputError unless `path` is a readable regular file
TextCompression detectCompression(const std::string& path);

/// \brief The path without a trailing ".gz" or ".bz2" ("a.clf.gz" -> "a.clf").
std::string withoutCompressionSuffix(const std::string& path);

/// \brief What a TextLineReader accepts.
struct TextLimits {
  /// \brief Longest line (bytes, without the newline).
  std::size_t max_line_bytes = std::size_t{1} << 20;
  /// \brief A compressed file may expand to max(min_expanded_bytes, max_expansion x its size).
  std::uint64_t max_expansion = 1000;
  std::uint64_t min_expanded_bytes = std::uint64_t{256} << 20;
};

/// \brief Reads a plain, gzip or bzip2 text file one line at a time; only one buffer and the
/// current line are in memory. Not thread-safe; one reader per thread.
class TextLineReader {
 public:
  /// \brief Open `path` and tell its compression from its first bytes.
  /// \throws InputError "PATH: cannot open (...)" unless it is a readable regular file
  explicit TextLineReader(const std::string& path, const TextLimits& limits = {});
  ~TextLineReader();
  TextLineReader(const TextLineReader&) = delete;
  TextLineReader& operator=(const TextLineReader&) = delete;

  /// \brief The next line without its '\n' (a '\r' before it is kept); a last line without a
  /// newline counts. \return false at the end of the text
  /// \throws InputError naming the file (and line) for a corrupt or truncated compressed stream,
  /// a line longer than the limit, or an expansion beyond the limit
  bool next(std::string& line);

  /// \brief 1-based number of the line `next` returned last (0 before the first).
  std::size_t lineNumber() const { return line_number_; }
  /// \brief Bytes of text read so far (after decompression).
  std::uint64_t textBytes() const { return text_bytes_; }
  TextCompression compression() const { return compression_; }
  const std::string& path() const { return path_; }

 private:
  bool fill();

  struct Stream;
  std::string path_;
  TextLimits limits_;
  TextCompression compression_ = TextCompression::None;
  std::unique_ptr<Stream> stream_;
  std::unique_ptr<char[]> buffer_;
  std::size_t begin_ = 0, end_ = 0;
  bool eof_ = false;
  std::size_t line_number_ = 0;
  std::uint64_t text_bytes_ = 0, expansion_limit_ = 0;
};

}  // namespace metricmap
