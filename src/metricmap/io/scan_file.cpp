#include "metricmap/io/scan_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

#include <pcl/PCLPointCloud2.h>

#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/npy_reader.h"

namespace metricmap {

const char* const kPointTimeFields[5] = {"t", "time", "timestamp", "time_stamp", "offset_time"};

namespace {

constexpr double kMaxSweepSeconds = 10.0;

bool hasExtension(const std::string& path, const char* ext) {
  const std::size_t n = std::strlen(ext);
  if (path.size() < n) return false;
  return std::equal(path.end() - static_cast<std::ptrdiff_t>(n), path.end(), ext,
                    [](char a, char b) { return std::tolower(a) == b; });
}

const pcl::PCLPointField* findField(const pcl::PCLPointCloud2& blob, const std::string& name) {
  for (const auto& f : blob.fields) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

// One value of a numeric field as double; `scale` turns integers into the wanted unit.
double readValue(const std::uint8_t* at, std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8:
      return static_cast<double>(*reinterpret_cast<const std::int8_t*>(at));
    case pcl::PCLPointField::UINT8:
      return static_cast<double>(*at);
    case pcl::PCLPointField::INT16: {
      std::int16_t v;
      std::memcpy(&v, at, 2);
      return v;
    }
    case pcl::PCLPointField::UINT16: {
      std::uint16_t v;
      std::memcpy(&v, at, 2);
      return v;
    }
    case pcl::PCLPointField::INT32: {
      std::int32_t v;
      std::memcpy(&v, at, 4);
      return v;
    }
    case pcl::PCLPointField::UINT32: {
      std::uint32_t v;
      std::memcpy(&v, at, 4);
      return v;
    }
    case pcl::PCLPointField::FLOAT32: {
      float v;
      std::memcpy(&v, at, 4);
      return v;
    }
    case pcl::PCLPointField::FLOAT64: {
      double v;
      std::memcpy(&v, at, 8);
      return v;
    }
    case pcl::PCLPointField::INT64: {
      std::int64_t v;
      std::memcpy(&v, at, 8);
      return static_cast<double>(v);
    }
    case pcl::PCLPointField::UINT64: {
      std::uint64_t v;
      std::memcpy(&v, at, 8);
      return static_cast<double>(v);
    }
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

std::size_t typeSize(std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8:
    case pcl::PCLPointField::UINT8:
      return 1;
    case pcl::PCLPointField::INT16:
    case pcl::PCLPointField::UINT16:
      return 2;
    case pcl::PCLPointField::INT32:
    case pcl::PCLPointField::UINT32:
    case pcl::PCLPointField::FLOAT32:
      return 4;
    case pcl::PCLPointField::FLOAT64:
    case pcl::PCLPointField::INT64:
    case pcl::PCLPointField::UINT64:
      return 8;
    default:
      return 0;
  }
}

// Seconds per unit of a time field of this type, or 0 when the type cannot hold a time.
double timeScale(std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::FLOAT32:
    case pcl::PCLPointField::FLOAT64:
      return 1.0;
    case pcl::PCLPointField::INT32:
    case pcl::PCLPointField::UINT32:
    case pcl::PCLPointField::INT64:
    case pcl::PCLPointField::UINT64:
      return 1e-9;
    default:
      return 0.0;
  }
}

void checkField(const std::string& path, const pcl::PCLPointField& f,
                const pcl::PCLPointCloud2& blob) {
  const std::size_t size = typeSize(f.datatype);
  if (size == 0 || f.count != 1 || f.offset > blob.point_step || size > blob.point_step - f.offset)
    throw InputError(path + ": field '" + f.name + "' is not one number inside each point");
}

void keepTimesRelative(const std::string& path, const std::string& field,
                       std::vector<double>& times) {
  double lo = times.front(), hi = times.front();
  for (double t : times) {
    if (!std::isfinite(t))
      throw InputError(path + ": time field '" + field + "' has a non-finite value");
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  if (hi - lo > kMaxSweepSeconds) {
    throw InputError(path + ": time field '" + field + "' spans " + formatNumber(hi - lo) +
                     " s, more than one sweep (at most 10 s; integer fields are read as ns)");
  }
  for (double& t : times) t -= lo;
}

ScanFile fromBlob(const std::string& path, const pcl::PCLPointCloud2& blob) {
  ScanFile out;
  const pcl::PCLPointField* x = findField(blob, "x");
  const pcl::PCLPointField* y = findField(blob, "y");
  const pcl::PCLPointField* z = findField(blob, "z");
  const pcl::PCLPointField* intensity = findField(blob, "intensity");
  const pcl::PCLPointField* time = nullptr;
  for (const char* name : kPointTimeFields) {
    if ((time = findField(blob, name))) break;
  }
  for (const pcl::PCLPointField* f : {x, y, z, intensity, time}) {
    if (f) checkField(path, *f, blob);
  }
  double time_scale = 0.0;
  if (time) {
    time_scale = timeScale(time->datatype);
    if (time_scale == 0.0) {
      throw InputError(path + ": time field '" + time->name +
                       "' is not float32/float64 (s) or a 32/64-bit integer (ns)");
    }
    out.time_field = time->name;
  }
  const std::size_t n = static_cast<std::size_t>(blob.width) * blob.height;
  out.points.reserve(n);
  if (intensity) out.intensity.reserve(n);
  if (time) out.point_times.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = blob.data.data() + i * blob.point_step;
    pcl::PointXYZ q;
    std::memcpy(&q.x, p + x->offset, 4);
    std::memcpy(&q.y, p + y->offset, 4);
    std::memcpy(&q.z, p + z->offset, 4);
    if (!(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z))) {
      ++out.nonfinite_dropped;
      continue;
    }
    out.points.push_back(q);
    if (intensity) {
      const double level = readValue(p + intensity->offset, intensity->datatype);
      if (beyondFloatRange(level)) {
        std::ostringstream msg;
        msg << path << ": point " << i << ": intensity " << level
            << " is beyond the float range (+-3.40282e+38) points are stored in";
        throw InputError(msg.str());
      }
      out.intensity.push_back(static_cast<float>(level));
    }
    if (time) out.point_times.push_back(readValue(p + time->offset, time->datatype) * time_scale);
  }
  return out;
}

ScanFile fromNpy(const NpyArray& a) {
  ScanFile out;
  out.points.reserve(a.rows);
  if (a.cols >= 4) out.intensity.reserve(a.rows);
  for (std::size_t r = 0; r < a.rows; ++r) {
    const double* v = &a.values[r * a.cols];
    const pcl::PointXYZ q(static_cast<float>(v[0]), static_cast<float>(v[1]),
                          static_cast<float>(v[2]));
    if (!(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z))) {
      ++out.nonfinite_dropped;
      continue;
    }
    out.points.push_back(q);
    if (a.cols >= 4) out.intensity.push_back(static_cast<float>(v[3]));
  }
  return out;
}

}  // namespace

ScanFile readScanFile(const std::string& path) {
  ScanFile out;
  std::size_t declared = 0;
  if (hasExtension(path, ".npy")) {
    const NpyArray a = readNpyPoints(path);
    declared = a.rows;
    out = fromNpy(a);
  } else {
    pcl::PCLPointCloud2 blob;
    loadCloudBlob(path, blob);
    declared = static_cast<std::size_t>(blob.width) * blob.height;
    out = fromBlob(path, blob);
  }
  if (out.points.empty()) {
    throw InputError(path + ": no finite points (" + std::to_string(declared) + " in the file)");
  }
  if (!out.point_times.empty()) keepTimesRelative(path, out.time_field, out.point_times);
  out.points.width = static_cast<std::uint32_t>(out.points.size());
  out.points.height = 1;
  out.points.is_dense = true;
  return out;
}

}  // namespace metricmap
