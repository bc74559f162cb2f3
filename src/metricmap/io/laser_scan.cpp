#include "metricmap/io/laser_scan.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/carmen_log.h"
#include "metricmap/io/input_file.h"
#include "metricmap/io/text_stream.h"

namespace metricmap {
namespace {

constexpr double kDeg = M_PI / 180.0;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Lines of CARMEN logs: FLASER/ROBOTLASER1 within this many lines or bytes tell the format
/// (Freiburg 079's first scan is on line 199, after its PARAM lines).
constexpr std::size_t kDetectLines = 1000;
constexpr std::uint64_t kDetectBytes = std::uint64_t{4} << 20;

/// What a kept scan costs in memory, checked against the budget as scans accumulate (a
/// compressed log can hold far more lines than its size suggests).
void chargeScan(const std::string& path, const LaserScan& scan, std::uint64_t& bytes) {
  bytes += sizeof(LaserScan) + 2 * sizeof(double) * scan.ranges.size();
  checkMemory(bytes, 1, path + ": scans read so far");
}

/// Every number in a log goes through the checked parser; a refused token makes the line malformed.
bool parseDouble(const std::string& s, double& v) {
  try {
    v = parseFiniteDouble(s, "scan value");
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream is(line);
  for (std::string t; is >> t;) out.push_back(t);
  return out;
}

void requireScans(const std::string& path, const ScanLog& log) {
  if (log.scans.empty()) {
    throw InputError(path + ": no scan found" +
                     (log.skipped_lines
                          ? " (" + std::to_string(log.skipped_lines) + " malformed lines skipped)"
                          : std::string()));
  }
  // Scans whose every beam is invalid (ranges zero, negative or beyond kMaxLaserRange) leave
  // nothing to segment or map: refused as a log without scans is.
  for (const LaserScan& scan : log.scans) {
    for (const double r : scan.ranges) {
      if (std::isfinite(r)) return;
    }
  }
  throw InputError(path + ": no valid beam in its " + std::to_string(log.scans.size()) +
                   " scan(s): every range is zero, negative or beyond 10 km");
}

void warnSkipped(const std::string& path, ScanLog& log) {
  if (log.skipped_lines > 0) {
    log.warnings.push_back(path + ": skipped " + std::to_string(log.skipped_lines) +
                           " malformed scan line(s)");
  }
}

/// Parse ranges tokens[first, first + n) into `scan`; false if one is not a number.
bool fillRanges(const std::vector<std::string>& t, std::size_t first, std::size_t n, double start,
                double step, double scale, double min_r, double max_r, LaserScan& scan) {
  scan.angles.resize(n);
  scan.ranges.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    double raw = 0.0;
    if (!parseDouble(t[first + k], raw)) return false;
    const double r = raw * scale;
    scan.angles[k] = start + step * static_cast<double>(k);
    scan.ranges[k] = (r >= min_r && r <= max_r && r > 0.0 && r <= kMaxLaserRange) ? r : kNaN;
  }
  return true;
}

enum class LineKind { Scan, Malformed, Other };

/// The loop every line-based log shares: `parse` turns one line's tokens into a scan, or says
/// the line is malformed (counted, warned about) or something else (ignored).
template <typename Parse>
ScanLog readEachLine(const std::string& path, Parse parse) {
  TextLineReader in(path);
  ScanLog log;
  std::uint64_t bytes = 0;
  std::string line;
  while (in.next(line)) {
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;
    LaserScan scan;
    switch (parse(t, scan)) {
      case LineKind::Scan:
        chargeScan(path, scan, bytes);
        log.scans.push_back(std::move(scan));
        break;
      case LineKind::Malformed:
        ++log.skipped_lines;
        break;
      case LineKind::Other:
        break;
    }
  }
  warnSkipped(path, log);
  requireScans(path, log);
  return log;
}

}  // namespace

std::size_t LaserScan::validBeams() const {
  std::size_t n = 0;
  for (double r : ranges) n += std::isfinite(r) ? 1 : 0;
  return n;
}

void validateLaserScan(const LaserScan& scan) {
  if (scan.angles.size() != scan.ranges.size())
    throw std::invalid_argument("scan has " + std::to_string(scan.angles.size()) + " angles but " +
                                std::to_string(scan.ranges.size()) + " ranges");
  constexpr double kTwoPi = 6.283185307179586;
  for (std::size_t k = 0; k < scan.angles.size(); ++k) {
    const double a = scan.angles[k];
    if (std::isfinite(a) && std::abs(a) <= kTwoPi) continue;
    std::ostringstream msg;
    msg << "beam " << k << ": angle " << a
        << " rad is not within [-2 pi, 2 pi] (angles first, then ranges)";
    throw std::invalid_argument(msg.str());
  }
}

ScanLineFormat urg04lxMinesFormat() {
  ScanLineFormat f;
  f.skip_tokens = 24;
  f.count = 682;
  f.angle_min_deg = -120.0;
  f.angle_increment_deg = 240.0 / 681.0;
  f.range_scale = 0.001;
  f.min_range = 0.020;
  return f;
}

void validateScanLineFormat(const ScanLineFormat& f) {
  if (f.count == 0) throw std::invalid_argument("--count must be > 0");
  if (!std::isfinite(f.angle_min_deg))
    throw std::invalid_argument("--angle-min-deg must be finite");
  if (!std::isfinite(f.angle_increment_deg) || f.angle_increment_deg == 0.0) {
    throw std::invalid_argument("--angle-increment-deg must be finite and non-zero");
  }
  if (!std::isfinite(f.range_scale) || !(f.range_scale > 0.0)) {
    throw std::invalid_argument("--range-scale must be a finite number > 0");
  }
  if (!(f.min_range >= 0.0) || std::isnan(f.max_range) || !(f.max_range > f.min_range)) {
    throw std::invalid_argument("ranges need 0 <= --min-range < --max-range");
  }
}

ScanLog readAngleRangeCsv(const std::string& path) {
  TextLineReader in(path);
  ScanLog log;
  LaserScan scan;
  std::string line;
  for (std::size_t n = 1; in.next(line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const auto comma = line.find(',');
    double a = 0.0, r = 0.0;
    if (comma == std::string::npos || !parseDouble(line.substr(0, comma), a) ||
        !parseDouble(line.substr(comma + 1), r)) {
      throw InputError(path + ": line " + std::to_string(n) + ": expected 'angle,range', got '" +
                       quoteForMessage(line) + "'");
    }
    if (!(std::fabs(a) <= 2.0 * M_PI)) {
      std::ostringstream msg;
      msg << path << ": line " << n << ": angle " << a
          << " is outside [-2 pi, 2 pi]: a beam's bearing in radians";
      throw InputError(msg.str());
    }
    scan.angles.push_back(a);
    scan.ranges.push_back(r > 0.0 && r <= kMaxLaserRange ? r : kNaN);
  }
  if (!scan.angles.empty()) log.scans.push_back(std::move(scan));
  requireScans(path, log);
  return log;
}

ScanLog readScanLines(const std::string& path, const ScanLineFormat& f) {
  validateScanLineFormat(f);
  return readEachLine(path, [&](const std::vector<std::string>& t, LaserScan& scan) {
    const bool ok =
        t.size() >= f.skip_tokens && t.size() - f.skip_tokens >= f.count &&
        fillRanges(t, f.skip_tokens, f.count, f.angle_min_deg * kDeg, f.angle_increment_deg * kDeg,
                   f.range_scale, f.min_range, f.max_range, scan);
    return ok ? LineKind::Scan : LineKind::Malformed;
  });
}

bool looksLikeCarmen(const std::string& path) {
  requireRegularFile(path);
  try {
    TextLineReader in(path);
    std::string line;
    for (std::size_t n = 0; n < kDetectLines && in.textBytes() <= kDetectBytes && in.next(line);
         ++n) {
      if (line.rfind("FLASER ", 0) == 0 || line.rfind("ROBOTLASER1 ", 0) == 0) return true;
    }
  } catch (const InputError&) {
    // A file that cannot be read as text (binary, damaged stream): not a CARMEN log.
  }
  return false;
}

ScanLogKind detectScanLog(const std::string& path) {
  requireRegularFile(path);
  const std::string plain = withoutCompressionSuffix(path);
  if (plain.size() > 4 && plain.compare(plain.size() - 4, 4, ".csv") == 0)
    return ScanLogKind::AngleRangeCsv;
  return looksLikeCarmen(path) ? ScanLogKind::Carmen : ScanLogKind::Unknown;
}

ScanLog readScanLog(const std::string& path, const ScanLineFormat* lines_format) {
  if (lines_format != nullptr) return readScanLines(path, *lines_format);
  switch (detectScanLog(path)) {
    case ScanLogKind::AngleRangeCsv:
      return readAngleRangeCsv(path);
    case ScanLogKind::Carmen:
      return readCarmenLog(path);
    case ScanLogKind::Unknown:
      // A compressed log whose text could not be read: its reader names the damage.
      if (detectCompression(path) != TextCompression::None) return readCarmenLog(path);
      break;
  }
  throw InputError(path +
                   ": cannot tell the log format (not .csv, no FLASER/ROBOTLASER1 lines); "
                   "give its layout (metricmap lines: --preset or --count)");
}

ScanLog readCarmenLog(const std::string& path) {
  CarmenLogReader reader(path);
  ScanLog log;
  std::uint64_t bytes = 0;
  CarmenLaser message;
  while (reader.next(message)) {
    chargeScan(path, message.scan, bytes);
    log.scans.push_back(std::move(message.scan));
  }
  log.skipped_lines = reader.skippedLines();
  warnSkipped(path, log);
  requireScans(path, log);
  return log;
}

pcl::PointCloud<pcl::PointXYZ> scanToCloud(const LaserScan& scan) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.resize(scan.ranges.size());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
    const double r = scan.ranges[k];
    if (std::isfinite(r)) {
      cloud[k] = pcl::PointXYZ(static_cast<float>(r * std::cos(scan.angles[k])),
                               static_cast<float>(r * std::sin(scan.angles[k])), 0.0f);
    } else {
      cloud[k] = pcl::PointXYZ(nan, nan, nan);
    }
  }
  cloud.width = static_cast<std::uint32_t>(cloud.size());
  cloud.height = 1;
  cloud.is_dense = false;
  return cloud;
}

}  // namespace metricmap
