#include "metricmap/io/npy_reader.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>

#include "metricmap/common/float_range.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

constexpr std::uint64_t kMaxNpyBytes = std::uint64_t{1} << 34;  // 16 GiB: larger is not a scan

std::size_t parseDimension(const std::string& path, const std::string& text) {
  if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos)
    throw InputError(path + ": bad shape entry '" + text.substr(0, 20) + "' in the .npy header");
  return static_cast<std::size_t>(std::stoull(text));
}

// The text after `'key'` and a colon (spaces skipped), or npos.
std::size_t valueAt(const std::string& header, const std::string& key) {
  const std::size_t k = header.find("'" + key + "'");
  if (k == std::string::npos) return std::string::npos;
  std::size_t i = header.find_first_not_of(" \t", k + key.size() + 2);
  if (i == std::string::npos || header[i] != ':') return std::string::npos;
  return header.find_first_not_of(" \t", i + 1);
}

/// The header dict's text and where the data starts (versions 1, 2 and 3).
std::string headerOf(const std::string& path, const std::string& bytes, std::size_t& data_at) {
  static const char kMagic[] = "\x93NUMPY";
  if (bytes.size() < 10 || bytes.compare(0, 6, kMagic, 6) != 0)
    throw InputError(path + ": not a .npy file (bad magic)");
  const auto major = static_cast<unsigned char>(bytes[6]);
  std::size_t header_len = 0, header_at = 0;
  if (major == 1) {
    header_len = static_cast<unsigned char>(bytes[8]) |
                 (static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8);
    header_at = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw InputError(path + ": truncated .npy header");
    for (int i = 0; i < 4; ++i) {
      header_len |= static_cast<std::size_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
    }
    header_at = 12;
  } else {
    throw InputError(path + ": unsupported .npy version " + std::to_string(major));
  }
  if (header_len > bytes.size() - header_at) throw InputError(path + ": truncated .npy header");
  data_at = header_at + header_len;
  return bytes.substr(header_at, header_len);
}

/// The element size of the header's dtype: '<f4' or '<f8'. The header is a Python dict
/// literal; only its three keys are read, without a regex (a hostile header may be 4 GiB long).
std::size_t itemSize(const std::string& path, const std::string& header) {
  const std::size_t at = valueAt(header, "descr");
  const std::size_t end =
      at == std::string::npos || header[at] != '\'' ? std::string::npos : header.find('\'', at + 1);
  if (end == std::string::npos) throw InputError(path + ": .npy header has no descr");
  const std::string descr = header.substr(at + 1, end - at - 1);
  if (descr == "<f4") return 4;
  if (descr == "<f8") return 8;
  throw InputError(path + ": .npy dtype '" + descr.substr(0, 16) +
                   "' is not a little-endian float32/float64 ('<f4', '<f8')");
}

/// C order required; the shape (N, C) with 3 to 64 columns.
void readShape(const std::string& path, const std::string& header, NpyArray& a) {
  std::size_t at = valueAt(header, "fortran_order");
  if (at == std::string::npos) throw InputError(path + ": .npy header has no fortran_order");
  if (header.compare(at, 4, "True") == 0)
    throw InputError(path + ": Fortran-ordered .npy arrays are not read");
  if (header.compare(at, 5, "False") != 0)
    throw InputError(path + ": .npy header has no fortran_order");
  at = valueAt(header, "shape");
  const std::string not_2d = path + ": .npy shape is not (N, C): a 2-D point array is expected";
  if (at == std::string::npos || header[at] != '(') throw InputError(not_2d);
  const std::size_t end = header.find(')', at);
  if (end == std::string::npos) throw InputError(not_2d);
  std::string dims = header.substr(at + 1, end - at - 1);
  dims.erase(std::remove_if(dims.begin(), dims.end(), [](char c) { return c == ' '; }), dims.end());
  if (!dims.empty() && dims.back() == ',') dims.pop_back();
  const std::size_t comma = dims.find(',');
  if (comma == std::string::npos || dims.find(',', comma + 1) != std::string::npos)
    throw InputError(not_2d);
  a.rows = parseDimension(path, dims.substr(0, comma));
  a.cols = parseDimension(path, dims.substr(comma + 1));
  if (a.cols < 3 || a.cols > 64)
    throw InputError(path + ": .npy shape (" + std::to_string(a.rows) + ", " +
                     std::to_string(a.cols) + ") has not 3 to 64 columns (x y z ...)");
}

}  // namespace

NpyArray readNpyPoints(const std::string& path) {
  const std::string bytes = readRegularFile(path, kMaxNpyBytes);
  std::size_t data_at = 0;
  const std::string header = headerOf(path, bytes, data_at);
  const std::size_t item = itemSize(path, header);
  NpyArray a;
  readShape(path, header, a);
  const std::size_t available = bytes.size() - data_at;
  if (a.rows > available / (a.cols * item) || a.rows * a.cols * item != available) {
    throw InputError(path + ": .npy data (" + std::to_string(available) +
                     " bytes) does not match the shape (" + std::to_string(a.rows) + ", " +
                     std::to_string(a.cols) + ")");
  }
  a.values.resize(a.rows * a.cols);
  const char* data = bytes.data() + data_at;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    if (item == 4) {
      float f;
      std::memcpy(&f, data + 4 * i, 4);
      a.values[i] = f;
    } else {
      std::memcpy(&a.values[i], data + 8 * i, 8);
      // x y z and intensity become floats: a value no float holds is refused, not made inf
      if (i % a.cols < 4 && beyondFloatRange(a.values[i])) {
        std::ostringstream msg;
        msg << path << ": row " << i / a.cols << " column " << i % a.cols << " ("
            << "xyzi"[i % a.cols] << ") holds " << a.values[i]
            << ", beyond the float range (+-3.40282e+38) points are stored in";
        throw InputError(msg.str());
      }
    }
  }
  return a;
}

}  // namespace metricmap
