#pragma once
/// \file scan_casting.h
/// \brief Scans from files cast into a LogOddsMap: KITTI frames (poses file, Tr, world), the
/// frames of any scan source at given poses, or PCD scans whose VIEWPOINT is the sensor pose. What
/// `metricmap occupancy` runs per input.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {

/// \brief What the scans cast so far gave (sums over the scans).
struct ScanCastTotals {
  std::size_t frames = 0, points = 0, beams = 0, cut = 0, non_finite = 0;
  double load_s = 0, insert_s = 0;
  std::vector<std::string> warnings;  ///< the readers' warnings (e.g. a PCD's header), in order
};

/// \brief Called after each scan with (scans done, scans to do).
using CastProgress = std::function<void(std::size_t, std::size_t)>;

/// \brief Cast frames[first, last) of a KITTI sequence into `map`: every point of each scan,
/// moved to `world` with the pose file and Tr, from the sensor's position. Every frame of the
/// range is checked to exist before any is read.
/// \throws InputError naming the file for a missing frame, a bad calib or pose file
void castKittiFrames(LogOddsMap& map, const KittiSequence& sequence,
                     const std::vector<std::size_t>& frames, std::size_t first, std::size_t last,
                     KittiWorld world, ScanCastTotals& totals, const CastProgress& progress = {});

/// \brief Cast frames[first, last) of any scan source into `map`: every point of each scan moved
/// by its pose (`poses[k]`: sensor -> map world for frames[k]), cast from the sensor's position.
/// \throws InputError naming the scan when it cannot be read; std::invalid_argument when the
/// counts of frames and poses differ
void castSourceFrames(LogOddsMap& map, ScanSource& source, const std::vector<std::size_t>& frames,
                      const std::vector<Eigen::Isometry3d>& poses, std::size_t first,
                      std::size_t last, ScanCastTotals& totals, const CastProgress& progress = {});

/// \brief Cast PCD scans paths[first, last) into `map`, each from its VIEWPOINT (sensor pose).
/// \throws InputError naming the file for a file that is not a PCD or has no VIEWPOINT line
void castPcdScans(LogOddsMap& map, const std::vector<std::string>& paths, std::size_t first,
                  std::size_t last, ScanCastTotals& totals, const CastProgress& progress = {});

/// \brief \throws InputError unless the PCD's header has a VIEWPOINT line (the beams' origin).
void requirePcdViewpoint(const std::string& path);

}  // namespace metricmap
