#include "metricmap/io/kitti_bin.h"

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {

void readKittiBin(const std::string& path, pcl::PCLPointCloud2& blob) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw InputError(path + ": not a regular file (a directory or a special file)");
  requireRegularFile(path);  // a FIFO would block the open
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(path + ": cannot read (not a regular file?)");
  if (size % 16 != 0) {
    throw InputError(path + ": size " + std::to_string(size) +
                     " is not a multiple of 16 bytes (float32 x y z intensity)");
  }
  const auto n = static_cast<std::uint64_t>(size) / 16;
  if (n > 0xFFFFFFFFull) throw InputError(path + ": too many points for one cloud");
  if (size == 0) throw InputError(path + ": empty file, no points");
  checkMemory(static_cast<std::uint64_t>(size), 2, path);  // the blob, then the cloud
  in.seekg(0);
  blob = pcl::PCLPointCloud2();
  const char* names[4] = {"x", "y", "z", "intensity"};
  for (std::uint32_t i = 0; i < 4; ++i) {
    pcl::PCLPointField f;
    f.name = names[i];
    f.offset = 4 * i;
    f.datatype = pcl::PCLPointField::FLOAT32;
    f.count = 1;
    blob.fields.push_back(f);
  }
  blob.point_step = 16;
  blob.width = static_cast<std::uint32_t>(n);
  blob.height = 1;
  blob.row_step = blob.point_step * blob.width;
  blob.is_dense = false;
  blob.data.resize(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(blob.data.data()), size)) {
    throw InputError(path + ": read error");
  }
}

}  // namespace metricmap
