#pragma once
/// \file localization_status.h
/// \brief What localising one scan gave, in 2D and 3D.

namespace metricmap {

/// \brief What one scan gave.
enum class LocalizationStatus {
  NotFound,   ///< global search: no pose reached the score
  Ambiguous,  ///< global search: a distinct pose scored within the margin of the best
  Waiting,    ///< not localised, and this scan was not searched (global_every_n_scans)
  Fixed,      ///< global search (or the initial pose) accepted: localised
  Tracked,    ///< matched from the prediction: localised
  Weak,       ///< matched from the prediction below track_min_score: not reported
  Lost        ///< the weak scan that made the localiser give the track up
};

/// \brief "not_found", "ambiguous", "waiting", "fixed", "tracked", "weak", "lost".
const char* statusName(LocalizationStatus status);

}  // namespace metricmap
