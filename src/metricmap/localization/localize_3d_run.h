#pragma once
/// \file localize_3d_run.h
/// \brief Localizer3D over the scans of a 3D source (a folder of clouds, KITTI, a bag): one
/// result per scan.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/localization/localizer_3d.h"

namespace metricmap {

class ScanSource;

/// \brief Called after each scan: (scans done, scans in all, the localiser so far).
using Localize3DProgress = std::function<void(std::size_t, std::size_t, const Localizer3D&)>;

/// \brief A finished run.
struct Localize3DRun {
  std::unique_ptr<Localizer3D> localizer;
  std::vector<Localization3D> results;  ///< one per scan, in the order of `frames`
  std::vector<double> stamps;           ///< each scan's stamp (NaN where it has none)
  double read_seconds = 0.0;            ///< reading the scans from the source
};

/// \brief Localise the scans `frames` of `source` in `map` (`config`, the source's sensor to
/// base transform), from `initial` (base -> map) when given.
/// \throws InputError naming the scan for a planar (2D) one; std::invalid_argument for a bad
/// configuration or initial pose; CapacityError for a map beyond the memory budget
Localize3DRun runLocalize3D(ScanSource& source, const std::vector<std::size_t>& frames,
                            const PointMap3D& map, const Localizer3DConfig& config,
                            const std::optional<Eigen::Isometry3d>& initial = {},
                            const Localize3DProgress& progress = {});

}  // namespace metricmap
