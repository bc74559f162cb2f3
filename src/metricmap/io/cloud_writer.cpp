#include "metricmap/io/cloud_writer.h"

#include <atomic>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

#include <pcl/exceptions.h>
#include <pcl/io/pcd_io.h>

#include "metricmap/io/output_set.h"

namespace metricmap {
namespace {

std::string temporaryName(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

void commit(const std::string& tmp, const std::string& path) {
  try {
    checkOutputPath(path);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write (rename failed)");
  }
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
  const std::string tmp = temporaryName(path);
  pcl::PCDWriter writer;
  int rc = -1;
  try {
    switch (format) {
      case PcdFormat::Ascii:
        rc = writer.writeASCII(tmp, cloud, 8);
        break;
      case PcdFormat::Binary:
        rc = writer.writeBinary(tmp, cloud);
        break;
      case PcdFormat::BinaryCompressed:
        rc = writer.writeBinaryCompressed(tmp, cloud);
        break;
    }
  } catch (const pcl::PCLException&) {
    rc = -1;
  }
  if (rc != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write PCD (missing directory or no permission?)");
  }
  commit(tmp, path);
}

void writeTextAtomic(const std::string& path, const std::string& text) {
  checkOutputPath(path);
  const std::string tmp = temporaryName(path);
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out << text;
    out.close();  // a full disk may only show at the final flush and close
    if (!out) {
      out.close();
      std::remove(tmp.c_str());
      throw std::runtime_error(path + ": write failed");
    }
  }
  commit(tmp, path);
}

template void savePcdAtomic(const std::string&, const pcl::PointCloud<pcl::PointXYZ>&, PcdFormat);
template void savePcdAtomic(const std::string&, const pcl::PointCloud<pcl::PointXYZI>&, PcdFormat);
template void savePcdAtomic(const std::string&, const pcl::PointCloud<pcl::PointXYZRGB>&,
                            PcdFormat);

}  // namespace metricmap
