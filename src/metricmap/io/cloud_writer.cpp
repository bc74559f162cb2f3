#include "metricmap/io/cloud_writer.h"

#include <sys/statvfs.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <locale>
#include <sstream>
#include <stdexcept>

#include <pcl/exceptions.h>
#include <pcl/io/pcd_io.h>

#include "metricmap/io/atomic_file.h"
#include "metricmap/io/checked_file.h"
#include "metricmap/io/output_set.h"

namespace metricmap {
namespace {

/// PCL's binary writers return -1 or throw without a reason: find one for the message.
std::string whyPclFailed(const std::string& path, std::uint64_t bytes) {
  std::string dir = std::filesystem::path(path).parent_path().string();
  if (dir.empty()) dir = ".";
  struct statvfs fs {};
  if (::access(dir.c_str(), W_OK) != 0) return std::strerror(errno);
  if (::statvfs(dir.c_str(), &fs) == 0 &&
      static_cast<std::uint64_t>(fs.f_bavail) * fs.f_frsize < bytes + 4096) {
    return std::strerror(ENOSPC);
  }
  return "PCL's PCD writer failed";
}

/// The ASCII body PCL's PCDWriter::writeASCII writes (precision 8, "nan", rgb as an unsigned
/// integer), with every write checked: PCL's own ASCII writer ignores a failed write.
template <typename PointT>
void writePcdAscii(const std::string& path, const pcl::PointCloud<PointT>& cloud) {
  const auto fields = pcl::getFields<PointT>();
  CheckedFile out(path);
  out.write(pcl::PCDWriter::generateHeader<PointT>(cloud) + "DATA ascii\n");
  std::ostringstream stream;
  stream.precision(8);
  stream.imbue(std::locale::classic());
  for (const PointT& point : cloud) {
    stream.str("");
    bool first = true;
    for (const pcl::PCLPointField& f : fields) {
      if (f.name == "_") continue;
      if (f.datatype != pcl::PCLPointField::FLOAT32)
        throw std::logic_error("writePcdAscii: only float fields are written");
      const int count = f.count == 0 ? 1 : static_cast<int>(f.count);
      for (int c = 0; c < count; ++c) {
        if (!first) stream << ' ';
        first = false;
        const char* at = reinterpret_cast<const char*>(&point) + f.offset + c * sizeof(float);
        if (f.name == "rgb") {
          std::uint32_t value;
          std::memcpy(&value, at, sizeof value);
          stream << value;
          continue;
        }
        float value;
        std::memcpy(&value, at, sizeof value);
        if (std::isnan(value)) {
          stream << "nan";
        } else {
          stream << value;
        }
      }
    }
    stream << '\n';
    out.write(stream.str());
  }
  out.close();
}

}  // namespace

PcdFormat parsePcdFormat(const std::string& name) {
  if (name == "ascii") return PcdFormat::Ascii;
  if (name == "binary") return PcdFormat::Binary;
  if (name == "binary_compressed") return PcdFormat::BinaryCompressed;
  throw std::invalid_argument("PCD format must be ascii, binary or binary_compressed, got '" +
                              name + "'");
}

template <typename PointT>
void savePcdAtomic(const std::string& path, const pcl::PointCloud<PointT>& cloud,
                   PcdFormat format) {
  checkOutputPath(path);
  const std::string tmp = temporaryPathFor(path);
  if (format == PcdFormat::Ascii) {
    try {
      writePcdAscii(tmp, cloud);
    } catch (...) {
      std::remove(tmp.c_str());
      throw;
    }
    commitTemporary(tmp, path);
    return;
  }
  // PCL's binary writers reserve the whole file first (fallocate) and report that failure.
  pcl::PCDWriter writer;
  int rc = -1;
  try {
    rc = format == PcdFormat::Binary ? writer.writeBinary(tmp, cloud)
                                     : writer.writeBinaryCompressed(tmp, cloud);
  } catch (const pcl::PCLException&) {
    rc = -1;
  }
  if (rc != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(outputDisplayName(path) + ": cannot write PCD (" +
                             whyPclFailed(path, cloud.size() * sizeof(PointT)) + ")");
  }
  commitTemporary(tmp, path);
}

void writeTextAtomic(const std::string& path, const std::string& text) {
  checkOutputPath(path);
  const std::string tmp = temporaryPathFor(path);
  try {
    CheckedFile out(tmp);
    out.write(text);
    out.close();  // a full disk may only show at the final flush and close
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  commitTemporary(tmp, path);
}

template void savePcdAtomic(const std::string&, const pcl::PointCloud<pcl::PointXYZ>&, PcdFormat);
template void savePcdAtomic(const std::string&, const pcl::PointCloud<pcl::PointXYZI>&, PcdFormat);
template void savePcdAtomic(const std::string&, const pcl::PointCloud<pcl::PointXYZRGB>&,
                            PcdFormat);

}  // namespace metricmap
