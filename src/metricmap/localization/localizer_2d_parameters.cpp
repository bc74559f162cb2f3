#include "metricmap/localization/localizer_2d_parameters.h"

#include <limits>
#include <stdexcept>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parameter_table.h"

namespace metricmap {
namespace {

using C = Localizer2DConfig;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr ParameterRange kNonNegative{0.0, kInf, false};  // finite, >= 0
constexpr ParameterRange kPositive{0.0, kInf, true};      // finite, > 0
constexpr ParameterRange kUnit{0.0, 1.0};
constexpr ParameterRange kScore{0.01, 0.99};
constexpr ParameterRange kHalfTurn{0.0, 180.0, true, false};

// Every field of Localizer2DConfig, declared once: the validator, --set and the command's own
// options, the Python module and the docs' table come from here.
const ParameterTable<C>& table() {
  static const ParameterTable<C> t(
      "localisation",
      {
          {"min_range", &C::min_range, "m", {0.0, 1e4}, "shorter beams are dropped"},
          {"max_range", &C::max_range, "m", {0.01, 1e4}, "longer beams are dropped (> min_range)"},
          {"voxel_filter",
           &C::voxel_filter,
           "m",
           {0.001, 10.0},
           "points kept for matching: one per square of this edge"},
          {"occupied_probability",
           &C::occupied_probability,
           "",
           {0.5, 1.0, true, true},
           "the matching grid's occupied cells"},
          {"free_probability",
           &C::free_probability,
           "",
           {0.0, 0.5, true, true},
           "the matching grid's free and unknown cells"},
          {"branch_and_bound_depth",
           &C::branch_and_bound_depth,
           "",
           {1.0, 16.0},
           "levels of the multi-resolution search grids"},
          {"global_coarsening",
           &C::global_coarsening,
           "",
           {1.0, 8.0},
           "the global search runs on the map coarsened this many times (1: the map)"},
          {"global_search_points",
           &C::global_search_points,
           "",
           {10.0, kInf},
           "points the global search scores, at most"},
          {"global_min_score", &C::global_min_score, "", kScore,
           "refined score a global fix must reach"},
          {"global_min_margin", &C::global_min_margin, "", kUnit,
           "search score a fix must have over the best distinct pose's"},
          {"global_max_crossing", &C::global_max_crossing, "", kUnit,
           "share of a fix's beams that may pass through walls"},
          {"global_crossing_clearance", &C::global_crossing_clearance, "m", kNonNegative,
           "crossings nearer the beam's end are not counted"},
          {"global_distinct_distance", &C::global_distinct_distance, "m", kPositive,
           "poses farther apart are distinct"},
          {"global_distinct_angle_deg", &C::global_distinct_angle_deg, "deg", kHalfTurn,
           "poses turned more are distinct"},
          {"global_min_motion", &C::global_min_motion, "m", kNonNegative,
           "a failed search is repeated after this much motion ..."},
          {"global_min_turn_deg", &C::global_min_turn_deg, "deg", kNonNegative,
           "... or this much turn ..."},
          {"global_every_n_scans",
           &C::global_every_n_scans,
           "",
           {1.0, kInf},
           "... or this many scans (without odometry: the only rule)"},
          {"initial_linear_window",
           &C::initial_linear_window,
           "m",
           {0.0, 100.0, true, false},
           "search half-width around a given initial pose"},
          {"initial_angular_window_deg", &C::initial_angular_window_deg, "deg", kHalfTurn,
           "search half-width around a given initial heading"},
          {"track_linear_window",
           &C::track_linear_window,
           "m",
           {0.0, 10.0},
           "tracking: correlative search half-width"},
          {"track_angular_window_deg",
           &C::track_angular_window_deg,
           "deg",
           {0.0, 180.0},
           "tracking: correlative search half-width"},
          {"track_angular_window_per_turn",
           &C::track_angular_window_per_turn,
           "",
           {0.0, 10.0},
           "tracking: share of the predicted turn added to the angular half-width"},
          {"translation_weight", &C::translation_weight, "", kNonNegative,
           "Gauss-Newton prior on the search's translation"},
          {"rotation_weight", &C::rotation_weight, "", kNonNegative,
           "Gauss-Newton prior on the search's heading"},
          {"refine_iterations", &C::refine_iterations, "", {1.0, 1000.0}, "Gauss-Newton steps"},
          {"track_min_score", &C::track_min_score, "", kScore,
           "a tracked scan scoring below is weak (kept for the prediction, not reported)"},
          {"lost_after_weak_scans",
           &C::lost_after_weak_scans,
           "",
           {1.0, 1e6},
           "weak scans in a row that make a loss (the global search takes over)"},
      });
  return t;
}

}  // namespace

std::vector<ParameterSpec> localizer2DParameterSchema() { return table().schema(); }

std::vector<std::string> localizer2DParameterNames() { return table().names(); }

std::string localizer2DParameter(const C& config, const std::string& name) {
  return table().text(config, name);
}

void setLocalizer2DParameter(C& config, const std::string& name, const std::string& value) {
  table().setText(config, name, value);
}

void validateLocalizer2DConfig(const Localizer2DConfig& c) {
  table().checkRanges(c);
  if (!(c.max_range > c.min_range))
    throw std::invalid_argument("max_range must be > min_range, got " + formatNumber(c.max_range) +
                                " <= " + formatNumber(c.min_range));
}

}  // namespace metricmap
