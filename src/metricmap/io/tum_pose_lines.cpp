#include "metricmap/io/tum_pose_lines.h"

#include <fstream>
#include <vector>

#include "metricmap/exceptions.h"

namespace metricmap {

void requireNoExtraPoses(const std::string& path, std::size_t frames, const std::string& noun) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  std::vector<char> block(1 << 16);
  std::size_t line = 1, poses = 0, column = 0;
  bool comment = false, content = false;
  const auto endLine = [&] {
    if (content && ++poses > frames) {
      throw InputError(path + ": line " + std::to_string(line) + " is a pose line beyond the " +
                       std::to_string(frames) + " " + noun +
                       "(s) given: frame k takes the k-th pose line, so the trajectory must "
                       "hold one line per " +
                       noun + ", in order");
    }
    ++line;
    column = 0;
    comment = content = false;
  };
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got; ++i) {
      const char c = block[static_cast<std::size_t>(i)];
      if (c == '\n') {
        endLine();
        continue;
      }
      if (column++ == 0 && c == '#') comment = true;
      if (!comment && c != ' ' && c != '\t' && c != '\r') content = true;
    }
  }
  endLine();  // a last line without a newline
}

}  // namespace metricmap
