#pragma once
/// \file byte_buffer.h
/// \brief Little helpers to write and read versioned binary buffers (mergeable accumulators
/// sent between processes). Reading is checked: a short or inconsistent buffer throws
/// metricmap::InputError, it never reads past the end.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "metricmap/exceptions.h"

namespace metricmap {

/// \brief Appends trivially copyable values in host byte order (a cluster is homogeneous; the
/// magic number of each format detects a byte-order mismatch).
class ByteWriter {
 public:
  explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "plain values only");
    const std::size_t at = out_.size();
    out_.resize(at + sizeof(T));
    std::memcpy(out_.data() + at, &value, sizeof(T));
  }

 private:
  std::vector<std::uint8_t>& out_;
};

/// \brief Reads values back; every read is bounds-checked. `what` names the buffer in errors.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size, std::string what)
      : data_(data), size_(size), what_(std::move(what)) {}
  template <typename T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>, "plain values only");
    if (size_ - at_ < sizeof(T)) fail("truncated");
    T value;
    std::memcpy(&value, data_ + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::size_t remaining() const { return size_ - at_; }
  /// \brief Throws InputError: "<what>: <reason>".
  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError(what_ + ": " + reason);
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
  std::string what_;
};

}  // namespace metricmap
