#include "metricmap/occupancy/octomap_quiet.h"

#include <cstdio>
#include <iostream>

#include <fcntl.h>
#include <unistd.h>

namespace metricmap {
namespace {

class MuteStderr {
 public:
  MuteStderr() {
    std::fflush(stderr);
    std::cerr.flush();
    saved_ = dup(STDERR_FILENO);
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) dup2(null, STDERR_FILENO);
    if (null >= 0) ::close(null);
  }
  ~MuteStderr() {
    std::fflush(stderr);
    std::cerr.flush();
    if (saved_ >= 0) {
      dup2(saved_, STDERR_FILENO);
      ::close(saved_);
    }
  }
  MuteStderr(const MuteStderr&) = delete;
  MuteStderr& operator=(const MuteStderr&) = delete;

 private:
  int saved_ = -1;
};

}  // namespace

LogOddsMap readOctomapQuietly(const std::string& path, const LogOddsParams& params,
                              const OctomapUse& use) {
  MuteStderr mute;
  return readOctomap(path, params, use);
}

OctomapExpansion inspectOctomapQuietly(const std::string& path, const LogOddsParams& params,
                                       const OctomapUse& use) {
  MuteStderr mute;
  return inspectOctomap(path, params, use);
}

void writeOctomapQuietly(const LogOddsMap& map, const std::string& path) {
  MuteStderr mute;
  writeOctomap(map, path);
}

}  // namespace metricmap
