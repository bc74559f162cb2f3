#include "metricmap/occupancy/octomap_file_check.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

constexpr int kMaxDepth = 16;  // OctoMap's tree depth: leaves at depth 16
constexpr long long kMaxNodes = 1LL << 50;
constexpr double kMinResolution = kOctomapMinResolution, kMaxResolution = kOctomapMaxResolution;

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw InputError(name + ": " + what);
}

/// Reads one header line ending in '\n' from `pos`; false at the end of the bytes.
bool nextLine(const std::string& bytes, std::size_t& pos, std::string& line) {
  if (pos >= bytes.size()) return false;
  const std::size_t end = bytes.find('\n', pos);
  if (end == std::string::npos) return false;
  line = bytes.substr(pos, end - pos);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  pos = end + 1;
  return true;
}

/// Walks a .bt tree without recursion: 2 bytes per node, bit pair (lsb first) per child:
/// 01 occupied leaf, 10 free leaf, 11 inner node, 00 no child.
void walkBinary(const std::string& bytes, std::size_t pos, OctomapFileInfo& info,
                const std::string& name) {
  std::vector<int> pending_depth{0};  // depths of inner nodes still to read, depth first
  while (!pending_depth.empty()) {
    const int depth = pending_depth.back();
    pending_depth.pop_back();
    if (pos + 2 > bytes.size())
      fail(name, "truncated tree data (node " + std::to_string(info.nodes) + ")");
    const auto a = static_cast<unsigned char>(bytes[pos]);
    const auto b = static_cast<unsigned char>(bytes[pos + 1]);
    pos += 2;
    ++info.nodes;
    const unsigned bits = a | (static_cast<unsigned>(b) << 8);
    std::vector<int> inner;
    for (int c = 0; c < 8; ++c) {
      const unsigned pair = (bits >> (2 * c)) & 3u;
      if (pair == 0) continue;
      if (depth + 1 > kMaxDepth) fail(name, "tree deeper than 16 levels");
      if (pair == 3) {
        inner.push_back(depth + 1);
      } else {
        ++info.nodes;
        ++info.leaves;
      }
    }
    if (inner.empty() && bits == 0) ++info.leaves;
    // children are read in order: push in reverse so the first is popped first
    for (auto it = inner.rbegin(); it != inner.rend(); ++it) pending_depth.push_back(*it);
  }
  if (pos != bytes.size())
    fail(name, std::to_string(bytes.size() - pos) + " bytes after the tree data");
}

/// Walks a .ot tree: per node a float log-odds and a child mask byte, children depth first.
void walkFull(const std::string& bytes, std::size_t pos, OctomapFileInfo& info,
              const std::string& name) {
  std::vector<int> pending_depth{0};
  while (!pending_depth.empty()) {
    const int depth = pending_depth.back();
    pending_depth.pop_back();
    if (pos + 5 > bytes.size())
      fail(name, "truncated tree data (node " + std::to_string(info.nodes) + ")");
    float value;
    std::memcpy(&value, bytes.data() + pos, 4);
    const auto mask = static_cast<unsigned char>(bytes[pos + 4]);
    pos += 5;
    ++info.nodes;
    if (!std::isfinite(value))
      fail(name, "non-finite log-odds at node " + std::to_string(info.nodes));
    if (mask == 0) {
      ++info.leaves;
      continue;
    }
    if (depth + 1 > kMaxDepth) fail(name, "tree deeper than 16 levels");
    for (int c = 7; c >= 0; --c) {
      if ((mask >> c) & 1u) pending_depth.push_back(depth + 1);
    }
  }
  if (pos != bytes.size())
    fail(name, std::to_string(bytes.size() - pos) + " bytes after the tree data");
}

}  // namespace

OctomapFileInfo checkOctomapBytes(const std::string& bytes, const std::string& name) {
  OctomapFileInfo info;
  std::size_t pos = 0;
  std::string line;
  if (!nextLine(bytes, pos, line)) fail(name, "not an OctoMap file (no header line)");
  if (line.rfind("# Octomap OcTree binary file", 0) == 0) {
    info.binary = true;
  } else if (line.rfind("# Octomap OcTree file", 0) == 0) {
    info.binary = false;
  } else {
    fail(name,
         "not an OctoMap file (first line is not '# Octomap OcTree file' or '# Octomap "
         "OcTree binary file')");
  }
  bool have_size = false, have_res = false, have_data = false, have_id = false;
  while (nextLine(bytes, pos, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    std::string token, value, extra;
    in >> token;
    if (token == "data") {
      have_data = true;
      break;
    }
    // "KEY VALUE", each key once: a second 'res' line would silently win otherwise
    if (!(in >> value) || (in >> extra))
      fail(name, "header line '" + quoteForMessage(line) + "' is not 'KEY VALUE'");
    bool* seen = token == "id" ? &have_id : token == "size" ? &have_size : &have_res;
    if (token != "id" && token != "size" && token != "res")
      fail(name, "unknown header line '" + quoteForMessage(line) + "'");
    if (*seen) fail(name, "header has two '" + token + "' lines");
    *seen = true;
    try {
      if (token == "id") {
        info.id = value;
      } else if (token == "size") {
        info.size = static_cast<std::size_t>(parseInteger(value, "size", 0, kMaxNodes));
      } else {
        info.resolution = parseFiniteDouble(value, "res");
        if (!(info.resolution >= kMinResolution && info.resolution <= kMaxResolution))
          throw std::invalid_argument("");
      }
    } catch (const std::invalid_argument&) {
      fail(name, "bad " + token + " line '" + quoteForMessage(line) + "' (" +
                     (token == "size" ? std::string("a node count")
                                      : "a voxel edge from 0.0001 to 1000 m") +
                     ")");
    }
  }
  if (!have_data) fail(name, "truncated header (no 'data' line)");
  if (!have_res) fail(name, "header has no 'res' line");
  if (!have_size) fail(name, "header has no 'size' line");
  if (info.binary && !info.id.empty() && info.id != "OcTree")
    fail(name, "tree type '" + info.id + "' is not supported (OcTree only)");
  if (!info.binary && info.id != "OcTree")
    fail(name, "tree type '" + info.id + "' is not supported (OcTree only)");
  info.data_offset = pos;
  if (info.size == 0) {
    if (pos != bytes.size()) fail(name, "data after an empty tree");
    return info;
  }
  // every node takes at least 2 (.bt: a quarter of a 2-byte parent record) or 5 bytes
  if (info.binary) {
    walkBinary(bytes, pos, info, name);
  } else {
    if ((bytes.size() - pos) / 5 < info.size) fail(name, "truncated tree data");
    walkFull(bytes, pos, info, name);
  }
  if (info.nodes != info.size)
    fail(name, "header announces " + std::to_string(info.size) + " nodes, the data holds " +
                   std::to_string(info.nodes));
  return info;
}

}  // namespace metricmap
