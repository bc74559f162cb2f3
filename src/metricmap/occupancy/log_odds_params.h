#pragma once
/// \file log_odds_params.h
/// \brief Parameters of a probabilistic voxel map (OctoMap's sensor model and defaults).

#include <cmath>
#include <limits>
#include <vector>

#include "metricmap/common/parameter_schema.h"

namespace metricmap {

/// \brief Sensor model and map layout of a LogOddsMap. Defaults equal OctoMap's.
struct LogOddsParams {
  /// \brief Voxel edge in metres (finite, > 0).
  double resolution = 0.1;
  /// \brief P(occupied | hit): log-odds added to a beam's endpoint voxel.
  double prob_hit = 0.7;
  /// \brief P(occupied | miss): log-odds added to every voxel a beam passes through.
  double prob_miss = 0.4;
  /// \brief Lower clamping bound, as a probability.
  double clamp_min = 0.1192;
  /// \brief Upper clamping bound, as a probability.
  double clamp_max = 0.971;
  /// \brief A voxel is occupied when its probability is >= this, free otherwise.
  double occupancy_threshold = 0.5;
  /// \brief Beams longer than this are cut here and mark no hit (>= kMinLogOddsMaxRange;
  /// infinity: no cut).
  double max_range = std::numeric_limits<double>::infinity();
};

/// \brief The shortest beam cut a map accepts (m): 1 mm, the CLI's smallest range.
inline constexpr double kMinLogOddsMaxRange = 1e-3;

/// \brief One field of LogOddsParams with its declaration.
struct LogOddsField {
  ParameterSpec spec;
  double LogOddsParams::*member;
};

/// \brief Every field of LogOddsParams, declared once (name, unit, range, doc, default).
const std::vector<LogOddsField>& logOddsFields();

/// \brief Throws std::invalid_argument naming the first bad value: a field outside its declared
/// range (logOddsFields), or clamp_min > clamp_max.
void validateLogOddsParams(const LogOddsParams& params);

/// \brief log(p / (1 - p)) as float, as OctoMap computes it.
inline float logOddsOf(double probability) {
  return static_cast<float>(std::log(probability / (1.0 - probability)));
}

/// \brief 1 - 1 / (1 + exp(l)).
inline double probabilityOf(float log_odds) {
  return 1.0 - 1.0 / (1.0 + std::exp(static_cast<double>(log_odds)));
}

}  // namespace metricmap
