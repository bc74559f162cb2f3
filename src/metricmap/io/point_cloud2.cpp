#include "metricmap/io/point_cloud2.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/common/memory_budget.h"

namespace metricmap {
namespace {

constexpr double kMaxSweepSeconds = 10.0;
/// The largest |beam angle| a LaserScan may give (rad): two turns either way.
constexpr double kMaxBeamAngle = 4.0 * 3.14159265358979323846;

struct Field {
  std::string name;
  std::uint32_t offset = 0, count = 0;
  std::uint8_t datatype = 0;
};

std::size_t typeSize(std::uint8_t datatype) {
  switch (datatype) {
    case 1:  // INT8
    case 2:  // UINT8
      return 1;
    case 3:  // INT16
    case 4:  // UINT16
      return 2;
    case 5:  // INT32
    case 6:  // UINT32
    case 7:  // FLOAT32
      return 4;
    case 8:  // FLOAT64
      return 8;
    default:
      return 0;
  }
}

// One value as double, from `size` bytes in the cloud's byte order.
double value(const std::uint8_t* at, std::uint8_t datatype, bool swap) {
  std::uint8_t b[8];
  const std::size_t n = typeSize(datatype);
  if (swap) {
    for (std::size_t k = 0; k < n; ++k) b[k] = at[n - 1 - k];
  } else {
    std::memcpy(b, at, n);
  }
  switch (datatype) {
    case 1:
      return static_cast<std::int8_t>(b[0]);
    case 2:
      return b[0];
    case 3: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case 4: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case 5: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case 6: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case 7: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
    default: {
      double v;
      std::memcpy(&v, b, 8);
      return v;
    }
  }
}

bool hostBigEndian() {
  const std::uint16_t one = 1;
  std::uint8_t b;
  std::memcpy(&b, &one, 1);
  return b == 0;
}

const Field* find(const std::vector<Field>& fields, const char* name) {
  for (const Field& f : fields)
    if (f.name == name) return &f;
  return nullptr;
}

/// The layout: every field inside point_step, no two overlapping (checked in offset order).
void checkFieldLayout(const std::vector<Field>& fields, std::uint32_t point_step,
                      MessageReader& r) {
  std::vector<std::pair<std::uint64_t, std::size_t>> spans;  // (offset, field)
  spans.reserve(fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const Field& f = fields[i];
    const std::size_t s = typeSize(f.datatype);
    if (s == 0) r.fail("field '" + f.name + "' has unknown datatype " + std::to_string(f.datatype));
    if (f.count == 0) r.fail("field '" + f.name + "' has count 0");
    const std::uint64_t end = std::uint64_t(f.offset) + std::uint64_t(s) * f.count;
    if (end > point_step)
      r.fail("field '" + f.name + "' (offset " + std::to_string(f.offset) + ", " +
             std::to_string(end - f.offset) + " bytes) reaches beyond point_step " +
             std::to_string(point_step));
    spans.emplace_back(f.offset, i);
  }
  std::sort(spans.begin(), spans.end());
  for (std::size_t k = 1; k < spans.size(); ++k) {
    const Field& g = fields[spans[k - 1].second];
    const Field& f = fields[spans[k].second];
    if (f.offset < std::uint64_t(g.offset) + std::uint64_t(typeSize(g.datatype)) * g.count)
      r.fail("fields '" + g.name + "' and '" + f.name + "' overlap");
  }
}

/// The fields a cloud is read from: x, y, z, and intensity and a per-point time when present.
struct CloudFields {
  const Field *x = nullptr, *y = nullptr, *z = nullptr, *intensity = nullptr, *time = nullptr;
  double time_scale = 0.0;  ///< to seconds: 1 for float fields, 1e-9 for integer ones (ns)
};

CloudFields cloudFields(const std::vector<Field>& fields, MessageReader& r) {
  CloudFields f;
  f.x = find(fields, "x");
  f.y = find(fields, "y");
  f.z = find(fields, "z");
  if (!f.x || !f.y || !f.z) r.fail("no x, y and z fields");
  f.intensity = find(fields, "intensity");
  for (const char* name : kPointTimeFields)
    if ((f.time = find(fields, name))) break;
  if (f.time) {
    f.time_scale = f.time->datatype == 7 || f.time->datatype == 8 ? 1.0 : 1e-9;
    if (typeSize(f.time->datatype) < 4)
      r.fail("time field '" + f.time->name +
             "' is not float32/float64 (s) or a 32-bit integer (ns)");
  }
  return f;
}

/// One point; false (and counted) when a coordinate is not finite. A finite value no float
/// holds is refused, not made inf: points are stored as float.
bool decodePoint(const std::uint8_t* p, const CloudFields& f, bool swap, std::uint64_t index,
                 MessageReader& r, ScanFile& c) {
  const double xyz[3] = {value(p + f.x->offset, f.x->datatype, swap),
                         value(p + f.y->offset, f.y->datatype, swap),
                         value(p + f.z->offset, f.z->datatype, swap)};
  const double level =
      f.intensity ? value(p + f.intensity->offset, f.intensity->datatype, swap) : 0;
  for (int a = 0; a < 4; ++a) {
    const double v = a < 3 ? xyz[a] : level;
    if (beyondFloatRange(v)) {
      std::ostringstream msg;
      msg << "point " << index << ": "
          << (a < 3 ? std::string(1, "xyz"[a]) : std::string("intensity")) << " = " << v
          << " is beyond the float range (+-3.40282e+38) points are stored in";
      r.fail(msg.str());
    }
  }
  pcl::PointXYZ q;
  q.x = static_cast<float>(xyz[0]);
  q.y = static_cast<float>(xyz[1]);
  q.z = static_cast<float>(xyz[2]);
  if (!(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z))) {
    ++c.nonfinite_dropped;
    return false;
  }
  c.points.push_back(q);
  if (f.intensity) c.intensity.push_back(static_cast<float>(level));
  if (f.time)
    c.point_times.push_back(value(p + f.time->offset, f.time->datatype, swap) * f.time_scale);
  return true;
}

/// Per-point times from the sweep's start, checked finite and within one sweep.
void normaliseSweepTimes(const Field& time, MessageReader& r, std::vector<double>& times) {
  if (times.empty()) return;
  double lo = times.front(), hi = lo;
  for (double t : times) {
    if (!std::isfinite(t)) r.fail("time field '" + time.name + "' has a non-finite value");
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  if (hi - lo > kMaxSweepSeconds)
    r.fail("time field '" + time.name + "' spans " + formatNumber(hi - lo) +
           " s, more than one sweep (at most 10 s; integer fields are read as ns)");
  for (double& t : times) t -= lo;
}

}  // namespace

CloudMessage decodePointCloud2(const std::uint8_t* data, std::size_t size,
                               MessageReader::Encoding encoding, const std::string& what) {
  MessageReader r(data, size, encoding, what);
  CloudMessage out;
  out.stamp = r.header();
  out.height = r.u32();
  out.width = r.u32();
  // A PointField is at least 13 bytes serialised (name length, offset, datatype, count).
  const std::uint32_t nfields = r.sequenceLength(13);
  std::vector<Field> fields(nfields);
  for (Field& f : fields) {
    f.name = r.string();
    f.offset = r.u32();
    f.datatype = r.u8();
    f.count = r.u32();
  }
  const bool big = r.boolean();
  const std::uint32_t point_step = r.u32();
  const std::uint32_t row_step = r.u32();
  const std::uint32_t data_size = r.sequenceLength(1);
  const std::uint8_t* bytes = r.bytes(data_size);
  (void)r.boolean();  // is_dense: NaN points are dropped whatever it says
  checkFieldLayout(fields, point_step, r);
  const std::uint64_t n = std::uint64_t(out.width) * out.height;
  if (std::uint64_t(out.width) * point_step > row_step)
    r.fail("row_step " + std::to_string(row_step) + " is less than width " +
           std::to_string(out.width) + " x point_step " + std::to_string(point_step));
  if (std::uint64_t(row_step) * out.height != data_size)
    r.fail("data holds " + std::to_string(data_size) + " bytes, not row_step " +
           std::to_string(row_step) + " x height " + std::to_string(out.height));
  const CloudFields f = cloudFields(fields, r);
  if (f.time) out.cloud.time_field = f.time->name;
  // Points are charged to the budget: 12 bytes each, plus intensity and time.
  checkMemory(
      n, 12 + (f.intensity ? 4 : 0) + (f.time ? 8 : 0),
      what + ": " + std::to_string(out.width) + " x " + std::to_string(out.height) + " points");
  ScanFile& c = out.cloud;
  c.points.reserve(n);
  if (f.intensity) c.intensity.reserve(n);
  if (f.time) c.point_times.reserve(n);
  const bool swap = big != hostBigEndian();
  for (std::uint32_t row = 0; row < out.height; ++row) {
    for (std::uint32_t col = 0; col < out.width; ++col) {
      const std::uint8_t* p = bytes + std::size_t(row) * row_step + std::size_t(col) * point_step;
      decodePoint(p, f, swap, std::uint64_t(row) * out.width + col, r, c);
    }
  }
  c.points.width = static_cast<std::uint32_t>(c.points.size());
  c.points.height = 1;
  c.points.is_dense = true;
  if (f.time) normaliseSweepTimes(*f.time, r, c.point_times);
  return out;
}

LaserMessage decodeLaserScan(const std::uint8_t* data, std::size_t size,
                             MessageReader::Encoding encoding, const std::string& what) {
  MessageReader r(data, size, encoding, what);
  LaserMessage out;
  out.stamp = r.header();
  const float angle_min = r.f32();
  (void)r.f32();  // angle_max
  const float angle_increment = r.f32();
  (void)r.f32();  // time_increment
  (void)r.f32();  // scan_time
  const float range_min = r.f32();
  const float range_max = r.f32();
  const std::uint32_t n = r.sequenceLength(4);
  if (!std::isfinite(angle_min) || !std::isfinite(angle_increment))
    r.fail("angle_min or angle_increment is not finite");
  // Beam angles within two turns either way: beyond, a float angle no longer names a direction
  // (at 1e30 its spacing is 7e22 rad) and a sweep of n beams is not a scan.
  const double last = double(angle_min) + double(n == 0 ? 0 : n - 1) * double(angle_increment);
  if (!(std::abs(double(angle_min)) <= kMaxBeamAngle && std::abs(last) <= kMaxBeamAngle)) {
    std::ostringstream msg;
    msg << "beam angles from angle_min " << angle_min << " by angle_increment " << angle_increment
        << " reach " << last << " rad, beyond +-4 pi";
    r.fail(msg.str());
  }
  out.scan.angles.resize(n);
  out.scan.ranges.resize(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    const float v = r.f32();
    out.scan.angles[k] = double(angle_min) + double(k) * double(angle_increment);
    const bool valid = std::isfinite(v) && v > 0.0f && !(v < range_min) && !(v > range_max) &&
                       double(v) <= kMaxLaserRange;
    out.scan.ranges[k] = valid ? double(v) : std::numeric_limits<double>::quiet_NaN();
  }
  const std::uint32_t ni = r.sequenceLength(4);
  if (ni != 0 && ni != n)
    r.fail(std::to_string(ni) + " intensities for " + std::to_string(n) + " ranges");
  out.intensity.resize(ni);
  for (float& v : out.intensity) v = r.f32();
  return out;
}

}  // namespace metricmap
