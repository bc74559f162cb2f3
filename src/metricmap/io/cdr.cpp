#include "metricmap/io/cdr.h"

#include <cstring>

#include "metricmap/exceptions.h"

namespace metricmap {

MessageReader::MessageReader(const std::uint8_t* data, std::size_t size, Encoding encoding,
                             std::string what)
    : data_(data), size_(size), encoding_(encoding), what_(std::move(what)) {
  if (encoding_ == Encoding::Cdr) {
    if (size_ < 4) fail("shorter than the CDR encapsulation header");
    // 0x0000 CDR_BE, 0x0001 CDR_LE (XCDR1); 0x0006/0x0007 the XCDR2 plain forms, which lay
    // out the final types of these messages the same way up to alignment of 8-byte values.
    if (data_[0] != 0 || (data_[1] != 0 && data_[1] != 1))
      fail("unsupported CDR encapsulation 0x" + std::to_string(data_[0]) + "/" +
           std::to_string(data_[1]) + " (expected CDR_LE or CDR_BE)");
    big_endian_ = data_[1] == 0;
    pos_ = origin_ = 4;
  }
}

void MessageReader::fail(const std::string& message) const {
  throw InputError(what_ + ": " + message);
}

void MessageReader::align(std::size_t n) {
  if (encoding_ != Encoding::Cdr) return;
  const std::size_t rel = (pos_ - origin_) % n;
  if (rel != 0) {
    need(n - rel);
    pos_ += n - rel;
  }
}

void MessageReader::need(std::size_t n) {
  if (n > size_ - pos_)
    fail("truncated (needs " + std::to_string(n) + " more bytes at byte " + std::to_string(pos_) +
         ", " + std::to_string(size_ - pos_) + " left)");
}

std::uint8_t MessageReader::u8() {
  need(1);
  return data_[pos_++];
}

std::uint32_t MessageReader::u32() {
  align(4);
  need(4);
  const std::uint8_t* p = data_ + pos_;
  pos_ += 4;
  if (big_endian_)
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           p[3];
  return (std::uint32_t(p[3]) << 24) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[1]) << 8) |
         p[0];
}

float MessageReader::f32() {
  const std::uint32_t bits = u32();
  float v;
  std::memcpy(&v, &bits, 4);
  return v;
}

std::string MessageReader::string() {
  const std::uint32_t n = u32();
  need(n);
  const char* p = reinterpret_cast<const char*>(data_ + pos_);
  pos_ += n;
  if (encoding_ == Encoding::Cdr) {
    if (n == 0) return std::string();  // some writers give an empty string no NUL
    if (p[n - 1] != '\0') fail("a string without its terminating NUL");
    return std::string(p, n - 1);
  }
  return std::string(p, n);
}

std::uint32_t MessageReader::sequenceLength(std::size_t element_size) {
  const std::uint32_t n = u32();
  if (element_size == 2 || element_size == 4 || element_size == 8) align(element_size);
  if (element_size > 0 && n > (size_ - pos_) / element_size)
    fail("a sequence of " + std::to_string(n) + " elements of " + std::to_string(element_size) +
         " bytes in the " + std::to_string(size_ - pos_) + " bytes left");
  return n;
}

const std::uint8_t* MessageReader::bytes(std::size_t n) {
  need(n);
  const std::uint8_t* p = data_ + pos_;
  pos_ += n;
  return p;
}

double MessageReader::header() {
  if (encoding_ == Encoding::Ros1) (void)u32();  // seq
  const std::int32_t sec = i32();
  const std::uint32_t nsec = u32();
  (void)string();  // frame_id
  return static_cast<double>(sec) + static_cast<double>(nsec) * 1e-9;
}

}  // namespace metricmap
