#include "metricmap/io/pcd_reader.h"

#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include <pcl/io/pcd_io.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/pcd_header.h"

namespace metricmap {
namespace {

std::uint8_t datatypeOf(const std::string& path, char type, int size) {
  using F = pcl::PCLPointField;
  switch (type) {
    case 'F':
      if (size == 4) return F::FLOAT32;
      if (size == 8) return F::FLOAT64;
      break;
    case 'I':
      if (size == 1) return F::INT8;
      if (size == 2) return F::INT16;
      if (size == 4) return F::INT32;
      if (size == 8) return F::INT64;
      break;
    case 'U':
      if (size == 1) return F::UINT8;
      if (size == 2) return F::UINT16;
      if (size == 4) return F::UINT32;
      if (size == 8) return F::UINT64;
      break;
  }
  throw InputError(path + ": TYPE " + std::string(1, type) + " with SIZE " + std::to_string(size) +
                   " is not a PCD field type");
}

void layout(const std::string& path, const PcdHeader& h, pcl::PCLPointCloud2& blob) {
  blob = pcl::PCLPointCloud2();
  std::uint32_t offset = 0;
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    pcl::PCLPointField f;
    f.name = h.fields[i];
    f.offset = offset;
    f.datatype = datatypeOf(path, h.types[i], h.sizes[i]);
    f.count = static_cast<std::uint32_t>(h.counts[i]);
    offset += static_cast<std::uint32_t>(h.sizes[i] * h.counts[i]);
    blob.fields.push_back(f);
  }
  blob.point_step = offset;
  blob.width = static_cast<std::uint32_t>(h.width);
  blob.height = static_cast<std::uint32_t>(h.height);
  blob.row_step = blob.point_step * blob.width;
  blob.is_dense = true;
  blob.data.resize(h.points * h.point_bytes);
}

}  // namespace

void readPcd(const std::string& path, pcl::PCLPointCloud2& blob, LoadReport& report) {
  const PcdHeader h = checkPcdFile(path, report.skipped_lines);
  report.has_viewpoint = h.has_viewpoint;
  for (int i = 0; i < 7; ++i) report.viewpoint[i] = h.viewpoint[i];
  report.format = "pcd " + h.data;
  if (h.zero_dimensions) {
    report.warnings.push_back(path + ": header says WIDTH 0 HEIGHT 0 but POINTS " +
                              std::to_string(h.points) + ": read as an unorganised cloud of " +
                              std::to_string(h.points) + " points (WIDTH " +
                              std::to_string(h.points) + " HEIGHT 1 would say so)");
  }
  // The body as PCL decodes it, then the cloud (up to 48 bytes a point).
  checkMemory(h.points, h.point_bytes + 48, path + " (" + std::to_string(h.points) + " points)");
  layout(path, h, blob);
  if (h.points == 0) return;
  pcl::PCDReader reader;
  int rc = -1;
  if (h.data == "ascii") {
    std::istringstream body(h.ascii_body);
    rc = reader.readBodyASCII(body, blob, pcl::PCDReader::PCD_V7);
    if (report.skipped_lines > 0) {
      report.warnings.push_back(path + ": skipped " + std::to_string(report.skipped_lines) +
                                " malformed line(s) in the ascii body");
    }
  } else {
    if (h.data_offset > 0xFFFFFFFFull) throw InputError(path + ": PCD header too long");
    std::ifstream in(path, std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                           std::istreambuf_iterator<char>());
    rc = reader.readBodyBinary(bytes.data(), blob, pcl::PCDReader::PCD_V7,
                               h.data == "binary_compressed",
                               static_cast<unsigned int>(h.data_offset));
  }
  if (rc < 0) throw InputError(path + ": pcl::io could not decode the " + h.data + " body");
}

}  // namespace metricmap
