#pragma once
/// \file localize_2d_run.h
/// \brief Localizer2D over the scans of a planar source (a CARMEN log): each scan's beams and
/// raw odometry, one result per scan.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "metricmap/localization/localizer_2d.h"

namespace metricmap {

class ScanSource;

/// \brief Called after each scan: (scans done, scans in all, the localiser so far).
using Localize2DProgress = std::function<void(std::size_t, std::size_t, const Localizer2D&)>;

/// \brief A finished run.
struct Localize2DRun {
  std::unique_ptr<Localizer2D> localizer;
  std::vector<Localization2D> results;  ///< one per scan, in the order of `frames`
  std::vector<double> stamps;           ///< each scan's stamp (NaN where it has none)
  double read_seconds = 0.0;            ///< reading the scans from the source
};

/// \brief Localise the scans `frames` of `source` in `map` (`config`, the source's laser offset
/// as sensor_to_base), from `initial` (map frame) when given.
/// \throws InputError naming the scan for one that is not a 2D laser scan or whose odometry is
/// not finite; std::invalid_argument for a bad configuration; CapacityError for a map beyond the
/// memory budget
Localize2DRun runLocalize2D(ScanSource& source, const std::vector<std::size_t>& frames,
                            const Map2D& map, const Localizer2DConfig& config,
                            const std::optional<Pose2D>& initial = {},
                            const Localize2DProgress& progress = {});

}  // namespace metricmap
