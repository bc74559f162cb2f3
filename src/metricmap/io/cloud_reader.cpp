#include "metricmap/io/cloud_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/io/ply_io.h>

#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/kitti_bin.h"
#include "metricmap/io/npy_reader.h"
#include "metricmap/io/pcd_reader.h"
#include "metricmap/io/ply_check.h"

namespace metricmap {
namespace {

std::string lowerExtension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void readPly(const std::string& path, pcl::PCLPointCloud2& blob, LoadReport& report) {
  checkPlyFile(path);
  report.format = "ply";
  pcl::PLYReader reader;
  if (reader.read(path, blob) < 0)
    throw InputError(path + ": pcl::io could not read this PLY file");
}

/// A NumPy (N, C >= 3) array as a cloud of float32 x y z (and intensity, the fourth column), as
/// the scan sources read it: every cloud-reading command takes the same files.
void readNpy(const std::string& path, pcl::PCLPointCloud2& blob, LoadReport& report) {
  const NpyArray a = readNpyPoints(path);
  report.format = "npy";
  if (a.rows > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(path + ": " + std::to_string(a.rows) + " rows, more than a cloud holds");
  }
  const std::uint32_t nf = a.cols >= 4 ? 4 : 3;
  const char* names[] = {"x", "y", "z", "intensity"};
  blob.fields.clear();
  for (std::uint32_t f = 0; f < nf; ++f) {
    pcl::PCLPointField field;
    field.name = names[f];
    field.offset = 4 * f;
    field.datatype = pcl::PCLPointField::FLOAT32;
    field.count = 1;
    blob.fields.push_back(field);
  }
  blob.width = static_cast<std::uint32_t>(a.rows);
  blob.height = 1;
  blob.point_step = 4 * nf;
  blob.row_step = blob.point_step * blob.width;
  blob.is_dense = false;
  blob.data.resize(static_cast<std::size_t>(blob.point_step) * a.rows);
  for (std::size_t r = 0; r < a.rows; ++r) {
    for (std::uint32_t f = 0; f < nf; ++f) {
      const float v = static_cast<float>(a.values[r * a.cols + f]);
      std::memcpy(blob.data.data() + r * blob.point_step + 4 * f, &v, 4);
    }
  }
}

void checkXyz(const std::string& path, const pcl::PCLPointCloud2& blob) {
  for (const char* name : {"x", "y", "z"}) {
    const auto it = std::find_if(blob.fields.begin(), blob.fields.end(),
                                 [&](const pcl::PCLPointField& f) { return f.name == name; });
    if (it == blob.fields.end()) throw InputError(path + ": no '" + name + "' field");
    if (it->datatype != pcl::PCLPointField::FLOAT32 || it->count != 1) {
      throw InputError(path + ": field '" + name + "' is not a single float32");
    }
  }
}

template <typename PointT>
void dropNonFinite(pcl::PointCloud<PointT>& cloud, LoadReport& report) {
  const std::size_t before = cloud.size();
  auto finite = [](const PointT& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  };
  if (!std::all_of(cloud.begin(), cloud.end(), finite)) {
    pcl::PointCloud<PointT> kept;
    kept.header = cloud.header;
    kept.sensor_origin_ = cloud.sensor_origin_;
    kept.sensor_orientation_ = cloud.sensor_orientation_;
    kept.reserve(before);
    for (const PointT& p : cloud) {
      if (finite(p)) kept.push_back(p);
    }
    cloud.swap(kept);
  }
  report.nonfinite_dropped = before - cloud.size();
  cloud.width = static_cast<std::uint32_t>(cloud.size());
  cloud.height = 1;
  cloud.is_dense = true;
}

}  // namespace

LoadReport loadCloudBlob(const std::string& path, pcl::PCLPointCloud2& blob) {
  LoadReport report;
  report.path = path;
  requireRegularFile(path);
  const std::string ext = lowerExtension(path);
  if (ext == "pcd") {
    readPcd(path, blob, report);
  } else if (ext == "ply") {
    readPly(path, blob, report);
  } else if (ext == "bin") {
    readKittiBin(path, blob);
    report.format = "kitti bin";
  } else if (ext == "npy") {
    readNpy(path, blob, report);
  } else {
    throw InputError(path + ": unknown extension (expected .pcd, .ply, .bin or .npy)");
  }
  for (const auto& f : blob.fields) report.fields.push_back(f.name);
  report.width = blob.width;
  report.height = blob.height;
  report.points_in_file = static_cast<std::uint64_t>(blob.width) * blob.height;
  checkXyz(path, blob);
  // pcl::fromPCLPointCloud2 indexes the first byte of the data even when there is none.
  if (report.points_in_file == 0 || blob.data.empty())
    throw InputError(path + ": no points (the file declares 0)");
  if (blob.point_step == 0 || blob.data.size() / blob.point_step < report.points_in_file)
    throw InputError(path + ": the point data is shorter than the declared point count");
  return report;
}

template <typename PointT>
LoadReport loadCloud(const std::string& path, pcl::PointCloud<PointT>& cloud) {
  pcl::PCLPointCloud2 blob;
  LoadReport report = loadCloudBlob(path, blob);
  pcl::fromPCLPointCloud2(blob, cloud);
  const double* v = report.viewpoint;  // the sensor pose (PCD VIEWPOINT; identity otherwise)
  cloud.sensor_origin_ = Eigen::Vector4f(static_cast<float>(v[0]), static_cast<float>(v[1]),
                                         static_cast<float>(v[2]), 0.0f);
  cloud.sensor_orientation_ = Eigen::Quaternionf(static_cast<float>(v[3]), static_cast<float>(v[4]),
                                                 static_cast<float>(v[5]), static_cast<float>(v[6]))
                                  .normalized();
  dropNonFinite(cloud, report);
  if (cloud.empty()) {
    throw InputError(path + ": no finite points (" + std::to_string(report.points_in_file) +
                     " in the file, " + std::to_string(report.nonfinite_dropped) + " NaN/Inf)");
  }
  return report;
}

template LoadReport loadCloud(const std::string&, pcl::PointCloud<pcl::PointXYZ>&);
template LoadReport loadCloud(const std::string&, pcl::PointCloud<pcl::PointXYZI>&);
template LoadReport loadCloud(const std::string&, pcl::PointCloud<pcl::PointXYZRGB>&);

}  // namespace metricmap
