#include "metricmap/io/text_stream.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ios>
#include <string>

#include <boost/iostreams/filter/bzip2.hpp>
#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filtering_streambuf.hpp>

#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 16;

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

TextCompression compressionOf(std::ifstream& in) {
  unsigned char magic[3] = {0, 0, 0};
  in.read(reinterpret_cast<char*>(magic), 3);
  const std::streamsize got = in.gcount();
  in.clear();
  in.seekg(0);
  if (got >= 2 && magic[0] == 0x1f && magic[1] == 0x8b) return TextCompression::Gzip;
  if (got >= 3 && magic[0] == 'B' && magic[1] == 'Z' && magic[2] == 'h')
    return TextCompression::Bzip2;
  return TextCompression::None;
}

/// What went wrong in a decompressor, in words (Boost's own message is "iostream error").
std::string describe(const std::ios_base::failure& e) {
  namespace bio = boost::iostreams;
  if (const auto* g = dynamic_cast<const bio::gzip_error*>(&e)) {
    switch (g->error()) {
      case bio::gzip::bad_crc:
        return "CRC mismatch";
      case bio::gzip::bad_length:
        return "length mismatch";
      case bio::gzip::bad_header:
        return "bad header";
      case bio::gzip::bad_footer:
        return "bad or missing footer";
      case bio::gzip::bad_method:
        return "unknown compression method";
      default:
        return "deflate data damaged or cut (zlib code " + std::to_string(g->zlib_error_code()) +
               ")";
    }
  }
  if (const auto* b = dynamic_cast<const bio::bzip2_error*>(&e)) {
    // bzip2's codes are extern constants, not usable as case labels.
    const int code = b->error();
    if (code == bio::bzip2::data_error) return "damaged data";
    if (code == bio::bzip2::data_error_magic) return "bad magic or unexpected end";
    if (code == bio::bzip2::unexpected_eof) return "unexpected end";
    return "bzip2 code " + std::to_string(code);
  }
  if (const auto* z = dynamic_cast<const bio::zlib_error*>(&e)) {
    return "deflate data damaged or cut (zlib code " + std::to_string(z->error()) + ")";
  }
  return e.what();
}

}  // namespace

/// The file and, for a compressed one, the decompressing chain over it (declared after the
/// file, so destroyed before it).
struct TextLineReader::Stream {
  std::ifstream file;
  boost::iostreams::filtering_streambuf<boost::iostreams::input> filter;
  std::streambuf* source = nullptr;
};

const char* compressionName(TextCompression c) {
  switch (c) {
    case TextCompression::Gzip:
      return "gzip";
    case TextCompression::Bzip2:
      return "bzip2";
    case TextCompression::None:
      break;
  }
  return "plain";
}

TextCompression detectCompression(const std::string& path) {
  std::ifstream in = openRegularFile(path);
  return compressionOf(in);
}

std::string withoutCompressionSuffix(const std::string& path) {
  if (endsWith(path, ".gz")) return path.substr(0, path.size() - 3);
  if (endsWith(path, ".bz2")) return path.substr(0, path.size() - 4);
  return path;
}

TextLineReader::TextLineReader(const std::string& path, const TextLimits& limits)
    : path_(path), limits_(limits), stream_(std::make_unique<Stream>()) {
  stream_->file = openRegularFile(path);
  compression_ = compressionOf(stream_->file);
  if (compression_ == TextCompression::None) {
    stream_->source = stream_->file.rdbuf();
  } else {
    if (compression_ == TextCompression::Gzip) {
      stream_->filter.push(boost::iostreams::gzip_decompressor());
    } else {
      stream_->filter.push(boost::iostreams::bzip2_decompressor());
    }
    stream_->filter.push(stream_->file);
    stream_->source = &stream_->filter;
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    const std::uint64_t ratio_limit =
        size > UINT64_MAX / limits_.max_expansion ? UINT64_MAX : size * limits_.max_expansion;
    expansion_limit_ = std::max(limits_.min_expanded_bytes, ratio_limit);
  }
  buffer_ = std::make_unique<char[]>(kBufferBytes);
}

TextLineReader::~TextLineReader() = default;

bool TextLineReader::fill() {
  if (eof_) return false;
  std::streamsize got = 0;
  try {
    got = stream_->source->sgetn(buffer_.get(), static_cast<std::streamsize>(kBufferBytes));
  } catch (const std::ios_base::failure& e) {
    // gzip_error, bzip2_error and zlib_error all derive from ios_base::failure.
    throw InputError(path_ + ": corrupt or truncated " + compressionName(compression_) +
                     " stream after " + std::to_string(text_bytes_) + " bytes of text (" +
                     describe(e) + ")");
  }
  if (got <= 0) {
    eof_ = true;
    return false;
  }
  begin_ = 0;
  end_ = static_cast<std::size_t>(got);
  text_bytes_ += end_;
  if (compression_ != TextCompression::None && text_bytes_ > expansion_limit_) {
    throw InputError(path_ + ": expands to more than " + std::to_string(expansion_limit_) +
                     " bytes of text (over " + std::to_string(limits_.max_expansion) +
                     " times its size: refused as a decompression bomb)");
  }
  return true;
}

bool TextLineReader::next(std::string& line) {
  line.clear();
  bool any = false;
  for (;;) {
    if (begin_ == end_ && !fill()) {
      if (!any) return false;
      ++line_number_;  // a last line without a newline
      return true;
    }
    any = true;
    const char* start = buffer_.get() + begin_;
    const auto* newline = static_cast<const char*>(std::memchr(start, '\n', end_ - begin_));
    const std::size_t take = newline ? static_cast<std::size_t>(newline - start) : end_ - begin_;
    if (line.size() + take > limits_.max_line_bytes) {
      throw InputError(path_ + ": line " + std::to_string(line_number_ + 1) + ": longer than " +
                       std::to_string(limits_.max_line_bytes) + " bytes");
    }
    line.append(start, take);
    begin_ += take;
    if (newline) {
      ++begin_;
      ++line_number_;
      return true;
    }
  }
}

}  // namespace metricmap
