#pragma once
/// \file global_search_3d.h
/// \brief The global search of Localizer3D (see localizer_3d.h): descriptor ranking over the
/// map's places, one guess per neighbourhood, ICP verification around each, acceptance by
/// structure overlap and margin over the best distinct pose.

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "metricmap/localization/localization_status.h"
#include "metricmap/localization/localizer_3d_config.h"
#include "metricmap/localization/map_places_3d.h"
#include "metricmap/slam3d/loop_verification.h"

namespace metricmap {

struct GlobalSearch3D {
  LocalizationStatus status = LocalizationStatus::NotFound;  ///< NotFound, Ambiguous or Fixed
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();    ///< sensor -> map (the best)
  double score = 0.0;                                        ///< its structure overlap
  double margin = 0.0;
  std::size_t candidates = 0;  ///< guesses verified
};

/// \brief The loop verification of slam3d for the guess `guess` (sensor -> map) of `scan`: the
/// map's points around the guess, ICP from it, overlap tests (config.verify).
LoopVerification verifyGuess(const std::vector<Eigen::Vector3d>& scan,
                             const std::vector<Eigen::Vector3f>& map_points,
                             const Eigen::Isometry3d& guess, const Localizer3DConfig& config);

/// \brief Search `places` of the map `map_points` for `scan` (sensor frame, finite points).
GlobalSearch3D searchGlobally(const std::vector<Eigen::Vector3d>& scan,
                              const std::vector<Eigen::Vector3f>& map_points,
                              const std::vector<MapPlace3D>& places,
                              const Localizer3DConfig& config);

}  // namespace metricmap
