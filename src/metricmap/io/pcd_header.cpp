#include "metricmap/io/pcd_header.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {

bool isAsciiValue(const std::string& s) {
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "nan" || lower == "inf" || lower == "-inf" || lower == "+inf") return true;
  try {
    return std::fabs(parseFiniteDouble(s, "value")) <= std::numeric_limits<float>::max();
  } catch (const std::invalid_argument&) {
    return false;
  }
}

namespace {

constexpr std::size_t kMaxHeaderLines = 4096;

/// The message with control bytes of quoted file text as \xHH: a NUL would end what() early.
[[noreturn]] void fail(const std::string& path, const std::string& what) {
  std::string safe;
  for (const char ch : what) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      safe += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    } else {
      safe += ch;
    }
  }
  throw InputError(path + ": " + safe);
}

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream is(line);
  for (std::string t; is >> t;) out.push_back(t);
  return out;
}

std::uint64_t parseCount(const std::string& path, const std::string& key, const std::string& s,
                         std::uint64_t max) {
  if (s.empty() || s[0] == '-' || s[0] == '+') fail(path, key + " '" + s + "' is not a count");
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
  // the whole token: "1\0X" must not read as 1
  if (errno != 0 || end != s.c_str() + s.size() || v > max)
    fail(path, key + " '" + s + "' is not a valid count");
  return v;
}

/// VIEWPOINT tx ty tz qw qx qy qz: finite numbers, a unit quaternion (to 0.01).
void parseViewpoint(const std::string& path, const std::vector<std::string>& t, PcdHeader& h) {
  if (t.size() != 8) fail(path, "VIEWPOINT needs 7 numbers (tx ty tz qw qx qy qz)");
  for (int i = 0; i < 7; ++i) {
    try {
      h.viewpoint[i] = parseFiniteDouble(t[i + 1], "VIEWPOINT");
    } catch (const std::invalid_argument& e) {
      fail(path, e.what());
    }
  }
  const double qn = h.viewpoint[3] * h.viewpoint[3] + h.viewpoint[4] * h.viewpoint[4] +
                    h.viewpoint[5] * h.viewpoint[5] + h.viewpoint[6] * h.viewpoint[6];
  if (!(qn > 1e-12)) fail(path, "VIEWPOINT quaternion is zero");
  // A rotation's quaternion has norm 1; beyond the TUM reader's tolerance (0.01) the line is
  // not a sensor pose written with limited digits, and normalising it would guess.
  if (!(std::fabs(std::sqrt(qn) - 1.0) <= 1e-2)) {
    fail(path, "VIEWPOINT quaternion (" + std::string(t[4]) + " " + std::string(t[5]) + " " +
                   std::string(t[6]) + " " + std::string(t[7]) + ") has norm " +
                   formatNumber(std::sqrt(qn)) + ", not 1 within 0.01: it is not a rotation");
  }
  h.has_viewpoint = true;
}

/// After the header's lines: the field tables agree, the dimensions give POINTS, the point size.
void finishHeader(const std::string& path, bool have_width, bool have_height, bool have_points,
                  PcdHeader& h) {
  if (h.data.empty()) fail(path, "not a PCD file (no DATA line in the header)");
  if (h.fields.empty()) fail(path, "PCD header has no FIELDS");
  if (h.counts.empty()) h.counts.assign(h.fields.size(), 1);
  if (h.sizes.size() != h.fields.size() || h.types.size() != h.fields.size() ||
      h.counts.size() != h.fields.size()) {
    fail(path, "PCD header: FIELDS, SIZE, TYPE and COUNT have different lengths");
  }
  if (!have_width && !have_height && have_points) {
    h.width = h.points;
    h.height = 1;
  }
  if (have_points && h.points > 0 && h.width == 0 && h.height == 0) {
    h.width = h.points;
    h.height = 1;
    h.zero_dimensions = true;
  }
  if (!have_points) h.points = h.width * h.height;
  if (h.width * h.height != h.points) {
    fail(path, "PCD header: WIDTH x HEIGHT (" + std::to_string(h.width) + " x " +
                   std::to_string(h.height) + ") differs from POINTS " + std::to_string(h.points));
  }
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    h.point_bytes += static_cast<std::uint64_t>(h.sizes[i]) * h.counts[i];
    h.values_per_point += static_cast<std::uint64_t>(h.counts[i]);
  }
}

void parseHeader(const std::string& path, std::istream& in, PcdHeader& h) {
  bool have_points = false, have_width = false, have_height = false;
  std::vector<std::pair<std::string, std::size_t>> seen;  // header keys and their lines
  std::string line;
  for (std::size_t n = 0; n < kMaxHeaderLines && std::getline(in, line); ++n) {
    h.data_offset += line.size() + 1;
    const std::vector<std::string> t = tokens(line);
    if (t.empty() || t[0][0] == '#') continue;
    const std::string& key = t[0];
    // each key once: a second VIEWPOINT (or WIDTH, FIELDS ...) would silently win otherwise
    const std::string canonical = key == "COLUMNS" ? "FIELDS" : key;
    for (const auto& [k, first_line] : seen) {
      if (k == canonical) {
        fail(path, "a second '" + quoteForMessage(key) + "' line in the header (lines " +
                       std::to_string(first_line) + " and " + std::to_string(n + 1) + ")");
      }
    }
    seen.emplace_back(canonical, n + 1);
    if (key == "FIELDS" || key == "COLUMNS") {
      h.fields.assign(t.begin() + 1, t.end());
    } else if (key == "SIZE") {
      for (std::size_t i = 1; i < t.size(); ++i) {
        const auto v = parseCount(path, "SIZE", t[i], 8);
        if (v != 1 && v != 2 && v != 4 && v != 8)
          fail(path, "SIZE " + t[i] + " is not 1, 2, 4 or 8");
        h.sizes.push_back(static_cast<int>(v));
      }
    } else if (key == "TYPE") {
      for (std::size_t i = 1; i < t.size(); ++i) {
        if (t[i].size() != 1 || std::strchr("FIU", t[i][0]) == nullptr) {
          fail(path, "TYPE '" + t[i] + "' is not F, I or U");
        }
        h.types.push_back(t[i][0]);
      }
    } else if (key == "COUNT") {
      for (std::size_t i = 1; i < t.size(); ++i) {
        const auto v = parseCount(path, "COUNT", t[i], 1u << 20);
        if (v == 0) fail(path, "COUNT 0 in the header");
        h.counts.push_back(static_cast<int>(v));
      }
    } else if (key == "WIDTH" && t.size() == 2) {
      h.width = parseCount(path, "WIDTH", t[1], 0xFFFFFFFFull);
      have_width = true;
    } else if (key == "HEIGHT" && t.size() == 2) {
      h.height = parseCount(path, "HEIGHT", t[1], 0xFFFFFFFFull);
      have_height = true;
    } else if (key == "POINTS" && t.size() == 2) {
      h.points = parseCount(path, "POINTS", t[1], 0xFFFFFFFFull);
      have_points = true;
    } else if (key == "VIEWPOINT") {
      parseViewpoint(path, t, h);
    } else if (key == "DATA") {
      if (t.size() != 2 || (t[1] != "ascii" && t[1] != "binary" && t[1] != "binary_compressed")) {
        fail(path, "DATA must be ascii, binary or binary_compressed");
      }
      h.data = t[1];
      break;
    }
  }
  finishHeader(path, have_width, have_height, have_points, h);
}

void checkAscii(const std::string& path, std::istream& in, PcdHeader& h, std::uint64_t& skipped) {
  std::uint64_t valid = 0, line_no = 0;
  std::string line;
  while (valid < h.points && std::getline(in, line)) {
    ++line_no;
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;
    if (t.size() != h.values_per_point) {
      ++skipped;
      continue;
    }
    for (const std::string& v : t) {
      if (!isAsciiValue(v)) {
        fail(path, "body line " + std::to_string(line_no) + ": '" + v.substr(0, 32) +
                       "' is not a number");
      }
    }
    ++valid;
    h.ascii_body += line;
    h.ascii_body += '\n';
  }
  if (valid < h.points) {
    fail(path, "truncated ascii body: " + std::to_string(valid) + " of " +
                   std::to_string(h.points) + " points");
  }
}

void checkBinary(const std::string& path, std::istream& in, const PcdHeader& h,
                 std::uint64_t file_size) {
  const std::uint64_t body = file_size - std::min(file_size, h.data_offset);
  const std::uint64_t need = h.points * h.point_bytes;
  if (h.data == "binary") {
    if (need > body) {
      fail(path, "truncated binary body: header needs " + std::to_string(need) +
                     " bytes, file has " + std::to_string(body));
    }
    return;
  }
  std::uint32_t sizes[2] = {0, 0};
  in.read(reinterpret_cast<char*>(sizes), sizeof(sizes));
  if (!in) fail(path, "truncated binary_compressed body (no size block)");
  if (sizes[1] != need) {
    fail(path, "binary_compressed body unpacks to " + std::to_string(sizes[1]) +
                   " bytes, header needs " + std::to_string(need));
  }
  if (static_cast<std::uint64_t>(sizes[0]) + 8 > body) {
    fail(path, "truncated binary_compressed body: " + std::to_string(sizes[0]) +
                   " compressed bytes announced, " + std::to_string(body) + " present");
  }
  if (need > 0 && sizes[0] == 0) fail(path, "binary_compressed body is empty");
  // An LZF token of at most 3 bytes unpacks to at most 264 bytes (ratio < 100).
  if (need > 100 * static_cast<std::uint64_t>(sizes[0]) + 1024) {
    fail(path, "binary_compressed body of " + std::to_string(sizes[0]) +
                   " bytes cannot unpack to the " + std::to_string(need) +
                   " bytes the header needs");
  }
}

}  // namespace

PcdHeader checkPcdFile(const std::string& path, std::uint64_t& skipped_lines) {
  requireRegularFile(path);  // a FIFO would block the open
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open: ") + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  if (end < 0) fail(path, "cannot read (not a regular file?)");
  const auto file_size = static_cast<std::uint64_t>(end);
  if (file_size == 0) fail(path, "empty file");
  in.seekg(0);
  PcdHeader h;
  parseHeader(path, in, h);
  if (h.points * h.point_bytes / std::max<std::uint64_t>(h.point_bytes, 1) != h.points) {
    fail(path, "PCD header: POINTS x point size overflows");
  }
  skipped_lines = 0;
  if (h.data == "ascii") {
    checkAscii(path, in, h, skipped_lines);
  } else {
    in.clear();
    in.seekg(static_cast<std::streamoff>(h.data_offset));
    checkBinary(path, in, h, file_size);
  }
  return h;
}

}  // namespace metricmap
