#include "metricmap/io/ply_check.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>

#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/pcd_header.h"

namespace metricmap {
namespace {

/// The ascii body: the lines of the elements before the vertices are skipped (one line per
/// instance), then every vertex line must hold `properties` numbers.
void checkAsciiVertices(std::istream& in, const std::string& path, std::uint64_t skip_lines,
                        std::uint64_t vertices, std::uint64_t properties,
                        std::uint64_t header_lines) {
  std::string line;
  std::uint64_t line_no = header_lines, done = 0;
  while (done < vertices && std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (skip_lines > 0) {
      --skip_lines;
      continue;
    }
    std::istringstream is(line);
    std::uint64_t n = 0;
    for (std::string token; is >> token; ++n) {
      if (n < properties && !isAsciiValue(token)) {
        throw InputError(path + ": line " + std::to_string(line_no) + ": '" +
                         quoteForMessage(token) + "' is not a number");
      }
    }
    if (n != properties) {
      throw InputError(path + ": line " + std::to_string(line_no) + ": " + std::to_string(n) +
                       " value(s), the vertex has " + std::to_string(properties) + " properties");
    }
    ++done;
  }
}

}  // namespace

void checkPlyFile(const std::string& path) {
  requireRegularFile(path);  // a FIFO would block the open
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size <= 0) throw InputError(path + ": empty file or not a regular file");
  in.seekg(0);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) {
    throw InputError(path + ": not a PLY file (no 'ply' magic line)");
  }
  std::uint64_t header_bytes = line.size() + 1, vertices = 0, properties = 0;
  std::uint64_t header_lines = 1, lines_before_vertices = 0;
  bool in_vertex = false, ended = false, ascii = false, vertex_seen = false;
  for (int n = 0; n < 4096 && std::getline(in, line); ++n) {
    header_bytes += line.size() + 1;
    ++header_lines;
    std::istringstream is(line);
    std::string key;
    is >> key;
    if (key == "end_header") {
      ended = true;
      break;
    }
    if (line.find('\0') != std::string::npos)
      throw InputError(path + ": NUL byte in the PLY header");
    if (key == "element") {
      std::string name, count_text, extra;
      is >> name >> count_text;
      long long count = -1;
      try {
        count = parseInteger(count_text, "element count", 0, 1LL << 40);
      } catch (const std::invalid_argument&) {
      }
      if (name.empty() || count < 0 || (is >> extra))
        throw InputError(path + ": bad PLY element line '" + quoteForMessage(line) + "'");
      in_vertex = name == "vertex";
      if (in_vertex) vertices = static_cast<std::uint64_t>(count);
      if (!in_vertex && !vertex_seen) lines_before_vertices += static_cast<std::uint64_t>(count);
      vertex_seen = vertex_seen || in_vertex;
    } else if (key == "property" && in_vertex) {
      std::string type, name;
      is >> type >> name;
      // PCL's PLY parser asserts on a list among the vertex properties; refuse it here.
      if (type == "list")
        throw InputError(path + ": PLY vertex element has a list property ('" +
                         quoteForMessage(line) + "'); only scalar vertex properties are read");
      static const char* const kScalar[] = {
          "char", "uchar", "short", "ushort", "int",   "uint",   "float",   "double",
          "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
      bool known = false;
      for (const char* t : kScalar) known = known || type == t;
      if (!known || name.empty())
        throw InputError(path + ": bad PLY property line '" + quoteForMessage(line) + "'");
      ++properties;
    } else if (key == "format") {
      std::string format;
      is >> format;
      ascii = format == "ascii";
    } else if (key == "obj_info") {
      // PCL sizes an organized cloud from obj_info num_cols / num_rows: they must be sane.
      std::string what, value;
      is >> what >> value;
      if (what == "num_cols" || what == "num_rows") {
        try {
          parseInteger(value, "obj_info " + what, 1, 1 << 20);
        } catch (const std::invalid_argument& e) {
          throw InputError(path + ": " + e.what());
        }
      }
    }
  }
  if (!ended) throw InputError(path + ": PLY header has no end_header");
  const std::uint64_t body = static_cast<std::uint64_t>(size) - header_bytes;
  if (properties == 0 && vertices > 0) throw InputError(path + ": PLY vertices have no properties");
  // Every vertex property takes at least one byte in any PLY encoding.
  if (vertices > 0 && vertices > body / properties) {
    throw InputError(path + ": PLY header announces " + std::to_string(vertices) +
                     " vertices, the body has room for at most " +
                     std::to_string(body / properties));
  }
  if (ascii && vertices > 0)
    checkAsciiVertices(in, path, lines_before_vertices, vertices, properties, header_lines);
}

}  // namespace metricmap
