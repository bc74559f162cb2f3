#pragma once
/// \file cdr.h
/// \brief A bounded reader of ROS message payloads: CDR (ROS 2: a 4-byte encapsulation header,
/// little or big endian, primitives aligned to their size from the end of that header) and the
/// ROS 1 serialization (little endian, packed). Every read checks the remaining bytes; a
/// length in the data is never trusted beyond them.

#include <cstddef>
#include <cstdint>
#include <string>

namespace metricmap {

/// \brief Reads one message. Errors throw InputError("<what>: ...").
class MessageReader {
 public:
  enum class Encoding { Cdr, Ros1 };
  /// \brief `what` names the message in errors ("bag.db3: topic /points, message 3").
  MessageReader(const std::uint8_t* data, std::size_t size, Encoding encoding, std::string what);

  bool bigEndian() const { return big_endian_; }
  Encoding encoding() const { return encoding_; }
  const std::string& what() const { return what_; }
  std::size_t remaining() const { return size_ - pos_; }

  std::uint8_t u8();
  bool boolean() { return u8() != 0; }
  std::uint32_t u32();
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  float f32();
  /// \brief A string: CDR counts its terminating NUL, ROS 1 does not.
  std::string string();
  /// \brief The length of a sequence of `element_size`-byte elements, checked against the
  /// remaining bytes; aligns to a primitive element (2, 4, 8 bytes) for CDR; other sizes are
  /// lower bounds of a struct element.
  std::uint32_t sequenceLength(std::size_t element_size);
  /// \brief `n` raw bytes (a uint8[] payload) starting here; advances past them.
  const std::uint8_t* bytes(std::size_t n);
  /// \brief std_msgs/Header: stamp (seconds as double), frame id; ROS 1's has a seq first.
  double header();
  [[noreturn]] void fail(const std::string& message) const;

 private:
  void align(std::size_t n);
  void need(std::size_t n);
  const std::uint8_t* data_;
  std::size_t size_, pos_ = 0, origin_ = 0;
  Encoding encoding_;
  bool big_endian_ = false;
  std::string what_;
};

}  // namespace metricmap
