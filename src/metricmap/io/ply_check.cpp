#include "metricmap/io/ply_check.h"

#include <cstdint>
#include <fstream>
#include <sstream>

#include "metricmap/exceptions.h"

namespace metricmap {

void checkPlyFile(const std::string& path) {
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
  bool in_vertex = false, ended = false;
  for (int n = 0; n < 4096 && std::getline(in, line); ++n) {
    header_bytes += line.size() + 1;
    std::istringstream is(line);
    std::string key;
    is >> key;
    if (key == "end_header") {
      ended = true;
      break;
    }
    if (key == "element") {
      std::string name;
      long long count = -1;
      is >> name >> count;
      if (!is || count < 0) throw InputError(path + ": bad PLY element line '" + line + "'");
      in_vertex = name == "vertex";
      if (in_vertex) vertices = static_cast<std::uint64_t>(count);
    } else if (key == "property" && in_vertex) {
      ++properties;
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
}

}  // namespace metricmap
