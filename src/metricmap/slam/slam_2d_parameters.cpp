#include "metricmap/slam/slam_2d_parameters.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <variant>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parse_number.h"

namespace metricmap {
namespace {

using Field = std::variant<double Slam2DConfig::*, std::size_t Slam2DConfig::*, int Slam2DConfig::*,
                           bool Slam2DConfig::*, double LogOddsParams::*>;

struct Entry {
  std::string name;
  Field field;
  std::string unit;
  ParameterRange range;
  std::string doc;
};

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr ParameterRange kPositive{0.0, kInf, true};      // finite, > 0
constexpr ParameterRange kNonNegative{0.0, kInf, false};  // finite, >= 0
constexpr ParameterRange kAtLeastOne{1.0, kInf};
constexpr ParameterRange kAnyCount{0.0, kInf};
constexpr ParameterRange kUnit{0.0, 1.0, false, false};
constexpr ParameterRange kHalfTurn{0.0, 180.0, true, false};

using C = Slam2DConfig;

// Every field of Slam2DConfig, declared once: the validator, --set, the Python properties and
// the docs' table come from here (the final map's fields come from logOddsFields, as map_*).
const Entry kSlamFields[] = {
    {"min_range", &C::min_range, "m", kNonNegative, "shorter beams are dropped"},
    {"max_range", &C::max_range, "m", kPositive,
     "longer beams are dropped (> min_range): no return, or too far to place"},
    {"voxel_filter", &C::voxel_filter, "m", kPositive,
     "points kept for matching: one per square of this edge"},
    {"resolution", &C::resolution, "m", kPositive, "cell edge of the submaps"},
    {"scans_per_submap", &C::scans_per_submap, "", kAtLeastOne,
     "nodes a submap receives before the next one starts"},
    {"prob_hit",
     &C::prob_hit,
     "",
     {0.5, 1.0, true, true},
     "submap sensor model: P(occupied | hit)"},
    {"prob_miss",
     &C::prob_miss,
     "",
     {0.0, 0.5, true, true},
     "submap sensor model: P(occupied | miss)"},
    {"node_min_distance", &C::node_min_distance, "m", kNonNegative,
     "distance moved since the last node that makes a scan a node"},
    {"node_min_angle_deg", &C::node_min_angle_deg, "deg", kNonNegative,
     "turn since the last node that makes a scan a node"},
    {"node_max_time", &C::node_max_time, "s", kPositive,
     "time since the last node that makes a scan a node"},
    {"local_linear_window",
     &C::local_linear_window,
     "m",
     {0.0, 10.0},
     "local correlative search half-width"},
    {"local_angular_window_deg",
     &C::local_angular_window_deg,
     "deg",
     {0.0, 180.0},
     "local correlative search half-width"},
    {"local_angular_window_per_turn",
     &C::local_angular_window_per_turn,
     "",
     {0.0, 10.0},
     "share of the predicted turn added to the local angular half-width"},
    {"weak_direction_min_gain", &C::weak_direction_min_gain, "", kUnit,
     "score gain over the prediction below which weak directions keep the prediction"},
    {"weak_direction_information",
     &C::weak_direction_information,
     "",
     {0.0, 1e6},
     "information (per cell squared) below which a translation direction is weak"},
    {"weak_direction_weight",
     &C::weak_direction_weight,
     "",
     {0.0, 1e6},
     "Gauss-Newton prior toward the prediction along weak directions (0: off)"},
    {"translation_weight", &C::translation_weight, "", kNonNegative,
     "Gauss-Newton prior on the search's translation"},
    {"rotation_weight", &C::rotation_weight, "", kNonNegative,
     "Gauss-Newton prior on the search's heading"},
    {"refine_iterations", &C::refine_iterations, "", {1.0, 1000.0}, "Gauss-Newton steps"},
    {"bicubic", &C::bicubic, "", {}, "Gauss-Newton on the bicubic surface (else bilinear)"},
    {"loop_linear_window",
     &C::loop_linear_window,
     "m",
     {0.0, 100.0, true, false},
     "loop search half-width"},
    {"loop_angular_window_deg", &C::loop_angular_window_deg, "deg", kHalfTurn,
     "loop search half-width"},
    {"loop_min_score",
     &C::loop_min_score,
     "",
     {0.0, 1.0, true, true},
     "mean hit probability a loop match must reach"},
    {"loop_max_distance",
     &C::loop_max_distance,
     "m",
     {0.0, kInf, false, false, false},
     "submaps whose centre is farther are not searched"},
    {"wide_min_node_gap", &C::wide_min_node_gap, "", kAnyCount,
     "submaps finished this many nodes before are also searched in the wide window"},
    {"wide_every_n_nodes", &C::wide_every_n_nodes, "", kAtLeastOne,
     "the wide search runs once in this many nodes"},
    {"wide_idle_nodes", &C::wide_idle_nodes, "", kAnyCount,
     "... and only when no loop was closed in this many nodes (0: always)"},
    {"wide_linear_window",
     &C::wide_linear_window,
     "m",
     {0.0, 100.0, true, false},
     "wide search half-width"},
    {"wide_angular_window_deg", &C::wide_angular_window_deg, "deg", kHalfTurn,
     "wide search half-width"},
    {"loop_every_n_nodes", &C::loop_every_n_nodes, "", kAtLeastOne,
     "nodes searched for loops: one in this many"},
    {"loop_min_node_gap", &C::loop_min_node_gap, "", kAnyCount,
     "submaps that received a node fewer than this many nodes ago are not searched"},
    {"loop_min_overlap", &C::loop_min_overlap, "", kUnit,
     "share of the node's points on cells a submap observed, for the submap to be searched"},
    {"loop_max_chi2",
     &C::loop_max_chi2,
     "",
     {0.0, kInf, true, false, false},
     "loop edges above this chi2 after an optimisation are removed"},
    {"loop_max_submaps", &C::loop_max_submaps, "", kAtLeastOne,
     "the near search takes the nearest this many submaps that pass the overlap test"},
    {"loop_search_points",
     &C::loop_search_points,
     "",
     {10.0, kInf},
     "points the loop search scores, at most"},
    {"branch_and_bound_depth",
     &C::branch_and_bound_depth,
     "",
     {1.0, 16.0},
     "levels of the multi-resolution grids"},
    {"edge_translation_sigma", &C::edge_translation_sigma, "m", kPositive,
     "of the edges between consecutive nodes"},
    {"edge_rotation_sigma_deg", &C::edge_rotation_sigma_deg, "deg", kPositive,
     "of the edges between consecutive nodes"},
    {"loop_translation_sigma", &C::loop_translation_sigma, "m", kPositive, "of loop edges"},
    {"loop_rotation_sigma_deg", &C::loop_rotation_sigma_deg, "deg", kPositive, "of loop edges"},
    {"optimize_every_n_nodes", &C::optimize_every_n_nodes, "", kAtLeastOne,
     "optimise when loops were added, once in this many nodes"},
    {"optimize_iterations", &C::optimize_iterations, "", kAtLeastOne,
     "Levenberg-Marquardt steps while running"},
    {"final_iterations", &C::final_iterations, "", kAtLeastOne,
     "Levenberg-Marquardt steps at the end"},
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> list = [] {
    std::vector<Entry> l(std::begin(kSlamFields), std::end(kSlamFields));
    for (const LogOddsField& f : logOddsFields())
      l.push_back(
          {"map_" + f.spec.name, f.member, f.spec.unit, f.spec.range, "final map: " + f.spec.doc});
    return l;
  }();
  return list;
}

ParameterKind kindOf(const Field& f) {
  if (std::holds_alternative<bool Slam2DConfig::*>(f)) return ParameterKind::Switch;
  if (std::holds_alternative<std::size_t Slam2DConfig::*>(f)) return ParameterKind::Count;
  if (std::holds_alternative<int Slam2DConfig::*>(f)) return ParameterKind::Integer;
  return ParameterKind::Real;
}

double valueOf(const Slam2DConfig& c, const Field& f) {
  if (auto d = std::get_if<double Slam2DConfig::*>(&f)) return c.**d;
  if (auto n = std::get_if<std::size_t Slam2DConfig::*>(&f)) return static_cast<double>(c.**n);
  if (auto i = std::get_if<int Slam2DConfig::*>(&f)) return c.**i;
  if (auto b = std::get_if<bool Slam2DConfig::*>(&f)) return c.**b ? 1.0 : 0.0;
  return c.map.*std::get<double LogOddsParams::*>(f);
}

const Entry& find(const std::string& name) {
  for (const Entry& e : entries())
    if (name == e.name) return e;
  std::string msg = "unknown SLAM parameter '" + quoteForMessage(name) + "'";
  const std::string near = nearestParameterName(name, slam2DParameterNames());
  if (!near.empty()) msg += " (did you mean " + near + "?)";
  throw std::invalid_argument(msg);
}

std::string text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::vector<ParameterSpec> slam2DParameterSchema() {
  const Slam2DConfig defaults;
  std::vector<ParameterSpec> out;
  for (const Entry& e : entries()) {
    const ParameterKind kind = kindOf(e.field);
    const std::string shown = kind == ParameterKind::Real ? formatNumber(valueOf(defaults, e.field))
                                                          : slam2DParameter(defaults, e.name);
    out.push_back({e.name, kind, e.unit, e.range, e.doc, shown});
  }
  return out;
}

void checkSlam2DParameterRanges(const Slam2DConfig& config) {
  for (const Entry& e : entries()) {
    checkParameter({e.name, kindOf(e.field), e.unit, e.range, e.doc, ""}, valueOf(config, e.field));
  }
}

std::vector<std::string> slam2DParameterNames() {
  std::vector<std::string> out;
  for (const Entry& e : entries()) out.push_back(e.name);
  return out;
}

std::string slam2DParameter(const Slam2DConfig& config, const std::string& name) {
  const Field& f = find(name).field;
  if (auto d = std::get_if<double Slam2DConfig::*>(&f)) return text(config.**d);
  if (auto n = std::get_if<std::size_t Slam2DConfig::*>(&f)) return std::to_string(config.**n);
  if (auto i = std::get_if<int Slam2DConfig::*>(&f)) return std::to_string(config.**i);
  if (auto b = std::get_if<bool Slam2DConfig::*>(&f)) return config.**b ? "true" : "false";
  return text(config.map.*std::get<double LogOddsParams::*>(f));
}

void setSlam2DParameter(Slam2DConfig& config, const std::string& name, const std::string& value) {
  const Field& f = find(name).field;
  if (auto d = std::get_if<double Slam2DConfig::*>(&f)) {
    config.** d = parseFiniteDouble(value, name);
  } else if (auto n = std::get_if<std::size_t Slam2DConfig::*>(&f)) {
    config.** n = static_cast<std::size_t>(
        parseInteger(value, name, 0, std::numeric_limits<std::int32_t>::max()));
  } else if (auto i = std::get_if<int Slam2DConfig::*>(&f)) {
    config.** i =
        static_cast<int>(parseInteger(value, name, std::numeric_limits<std::int32_t>::min(),
                                      std::numeric_limits<std::int32_t>::max()));
  } else if (auto b = std::get_if<bool Slam2DConfig::*>(&f)) {
    if (value != "true" && value != "false")
      throw std::invalid_argument(name + ": '" + quoteForMessage(value) + "' is not true or false");
    config.** b = value == "true";
  } else {
    config.map.*std::get<double LogOddsParams::*>(f) = parseFiniteDouble(value, name);
  }
}

double slam2DParameterValue(const Slam2DConfig& config, const std::string& name) {
  return valueOf(config, find(name).field);
}

void setSlam2DParameterValue(Slam2DConfig& config, const std::string& name, double value) {
  const Entry& e = find(name);
  const ParameterKind kind = kindOf(e.field);
  if (kind == ParameterKind::Switch && value != 0.0 && value != 1.0)
    throw std::invalid_argument(name + " must be true or false");
  if (kind == ParameterKind::Count || kind == ParameterKind::Integer) {
    const double lo = kind == ParameterKind::Count ? 0.0 : -2147483648.0;
    const double hi = kind == ParameterKind::Count ? 18446744073709549568.0 : 2147483647.0;
    if (!(value == std::floor(value) && value >= lo && value <= hi))
      throw std::invalid_argument(name + " must be a whole number in [" + text(lo) + ", " +
                                  text(hi) + "], got " + text(value));
  }
  const Field& f = e.field;
  if (auto d = std::get_if<double Slam2DConfig::*>(&f)) {
    config.** d = value;
  } else if (auto n = std::get_if<std::size_t Slam2DConfig::*>(&f)) {
    config.** n = static_cast<std::size_t>(value);
  } else if (auto k = std::get_if<int Slam2DConfig::*>(&f)) {
    config.** k = static_cast<int>(value);
  } else if (auto b = std::get_if<bool Slam2DConfig::*>(&f)) {
    config.** b = value != 0.0;
  } else {
    config.map.*std::get<double LogOddsParams::*>(f) = value;
  }
}

bool isLoopClosureParameter(const std::string& name) {
  return name.rfind("loop_", 0) == 0 || name.rfind("wide_", 0) == 0 ||
         name == "branch_and_bound_depth";
}

}  // namespace metricmap
