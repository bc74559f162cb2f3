#pragma once
/// \file laser_scan.h
/// \brief 2D laser scans: readers for CSV "angle,range", one-scan-per-line logs (URG/Mines and
/// generic), CARMEN FLASER/ROBOTLASER1 logs; conversion to an ordered PCL cloud. Every reader
/// takes plain, gzip or bzip2 files (TextLineReader: lines up to 1 MiB, scans charged to the
/// memory budget).

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace metricmap {

/// \brief The farthest range any 2D laser reports (10 km, the bound of the odometry's
/// --max-range): a larger value in a log (1e39, a garbled token) is no return, an invalid beam
/// as a zero range is, in every reader (CSV, one-scan-per-line logs, CARMEN); never a point.
inline constexpr double kMaxLaserRange = 1e4;

/// \brief One scan: beam k has angles[k] (radians, counter-clockwise, x forward) and ranges[k]
/// (metres; NaN where the beam is invalid).
struct LaserScan {
  std::vector<double> angles;
  std::vector<double> ranges;
  std::size_t validBeams() const;
};

/// \brief The rules a scan handed to an algorithm obeys: as many angles as ranges, every angle
/// finite and within [-2 pi, 2 pi] rad. A range in the angles' place (a (ranges, angles) call where
/// (angles, ranges) is meant) usually breaks the last rule. \throws std::invalid_argument naming
/// the first beam that breaks a rule
void validateLaserScan(const LaserScan& scan);

/// \brief Scans read from a file, plus what was skipped.
struct ScanLog {
  std::vector<LaserScan> scans;
  std::size_t skipped_lines = 0;      ///< lines that could not be a scan (reported, not fatal)
  std::vector<std::string> warnings;  ///< one line each, naming the file
};

/// \brief How to read a log with one scan per line.
struct ScanLineFormat {
  std::size_t skip_tokens = 0;       ///< tokens before the first range
  std::size_t count = 0;             ///< ranges per scan (> 0)
  double angle_min_deg = 0.0;        ///< angle of beam 0
  double angle_increment_deg = 1.0;  ///< between beams
  double range_scale = 1.0;          ///< multiply raw ranges to get metres (> 0)
  double min_range = 0.0;            ///< metres; smaller ranges are invalid
  double max_range = std::numeric_limits<double>::infinity();  ///< larger ranges are invalid
};

/// \brief The Mines ParisTech URG-04LX logs (BreezySLAM exp*.dat): skip 24 tokens, 682 ranges
/// in mm over 240 degrees from -120, ranges under 20 mm invalid.
ScanLineFormat urg04lxMinesFormat();

/// \throws std::invalid_argument naming the bad value
void validateScanLineFormat(const ScanLineFormat& format);

/// \brief One scan from "angle,range" lines (radians, metres; CRLF allowed). Ranges <= 0 are
/// invalid beams. \throws InputError naming the file and line
ScanLog readAngleRangeCsv(const std::string& path);

/// \brief One scan per line. A line with too few tokens or a non-numeric range is skipped,
/// counted and warned about. \throws InputError when the file is unreadable or has no scan
ScanLog readScanLines(const std::string& path, const ScanLineFormat& format);

/// \brief CARMEN logs (carmen_log.h; plain, .gz or .bz2): the beams of every FLASER (180
/// degrees from -90: step pi/(n-1) for an odd count such as 181 or 361, else pi/n) and
/// ROBOTLASER1 (start, resolution and maximum range from the line); other lines are ignored,
/// malformed scan lines skipped, counted and warned about. Stamps and odometry: CarmenLogReader.
/// \throws InputError when the file is unreadable or damaged or has no scan
/// \throws CapacityError when the scans do not fit in the memory budget
ScanLog readCarmenLog(const std::string& path);

/// \brief True when the (decompressed) file has a FLASER or ROBOTLASER1 line within its first
/// 1000 lines or 4 MiB; false too for a file that cannot be read as text (damaged stream, a
/// line over 1 MiB). \throws InputError unless `path` is a readable regular file
bool looksLikeCarmen(const std::string& path);

/// \brief The layout of a 2D scan log, told from the file when not given.
enum class ScanLogKind { Unknown, AngleRangeCsv, Carmen };

/// \brief .csv (also .csv.gz, .csv.bz2) -> AngleRangeCsv; FLASER/ROBOTLASER1 lines -> Carmen;
/// else Unknown (a scan-per-line log needs its ScanLineFormat). \throws InputError for a file
/// that is not a readable regular file
ScanLogKind detectScanLog(const std::string& path);

/// \brief Read a scan log: with `lines_format`, one scan per line in that layout; without, the
/// layout detectScanLog finds (a compressed file whose text cannot be told is read as CARMEN, so
/// that its damage is named). \throws InputError naming the file when the layout cannot be
/// told or the file is bad
ScanLog readScanLog(const std::string& path, const ScanLineFormat* lines_format = nullptr);

/// \brief Ordered cloud, one point per beam (x = r cos a, y = r sin a, z = 0; NaN if invalid).
pcl::PointCloud<pcl::PointXYZ> scanToCloud(const LaserScan& scan);

}  // namespace metricmap
