#pragma once
// Shared by the fuzz targets: the input bytes as a temporary file with a chosen extension.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

namespace metricmap::fuzz {

/// \brief Writes the bytes to /tmp/metricmap_fuzz_PID_TAG.EXT; removed when it goes out of scope.
class TempInput {
 public:
  TempInput(const std::uint8_t* data, std::size_t size, const std::string& tag,
            const std::string& ext)
      : path_("/tmp/metricmap_fuzz_" + std::to_string(::getpid()) + "_" + tag + ext) {
    std::ofstream(path_, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~TempInput() { std::remove(path_.c_str()); }
  TempInput(const TempInput&) = delete;
  TempInput& operator=(const TempInput&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace metricmap::fuzz
