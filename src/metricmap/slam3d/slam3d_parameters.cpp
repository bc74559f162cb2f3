#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/slam3d/slam3d_config.h"

namespace metricmap {
namespace {

using C = Slam3DConfig;
using Field = std::variant<double C::*, std::size_t C::*, int C::*>;

struct Entry {
  const char* name;
  Field field;
  const char* unit;
  ParameterRange range;
  const char* doc;
};

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr ParameterRange kPositive{0.0, kInf, true};
constexpr ParameterRange kNonNegative{0.0, kInf, false};
constexpr ParameterRange kAtLeastOne{1.0, 1e6};
constexpr ParameterRange kCount{0.0, 1e6};
constexpr ParameterRange kUnit{0.0, 1.0};

const Entry kFields[] = {
    {"min_range", &C::min_range, "m", kNonNegative, "points closer to the sensor are dropped"},
    {"max_range", &C::max_range, "m", kPositive, "points farther are dropped (> min_range)"},
    {"voxel", &C::voxel, "m", {0.05, 10.0}, "each node keeps one point per voxel of this edge"},
    {"local_window",
     &C::local_window,
     "",
     {0.0, 50.0},
     "a node's local map: its scan and this many scans either side"},
    {"local_voxel", &C::local_voxel, "m", {0.05, 10.0}, "local maps: one point per voxel"},
    {"sc_rings", &C::sc_rings, "", {1.0, 200.0}, "Scan Context range bins"},
    {"sc_sectors", &C::sc_sectors, "", {4.0, 720.0}, "Scan Context azimuth bins"},
    {"sc_max_radius", &C::sc_max_radius, "m", kPositive, "Scan Context radius"},
    {"sc_height_offset",
     &C::sc_height_offset,
     "m",
     {-100.0, 100.0},
     "added to heights above the sensor before binning (bins below 0 stay empty)"},
    {"sc_candidates", &C::sc_candidates, "", kCount,
     "nearest ring keys compared in full (0: no descriptor search)"},
    {"sc_max_distance", &C::sc_max_distance, "", kUnit,
     "Scan Context distance a descriptor candidate must be below"},
    {"loop_min_travel", &C::loop_min_travel, "m", kNonNegative,
     "a candidate lies at least this far back along the path"},
    {"loop_radius", &C::loop_radius, "m", kNonNegative,
     "nodes within this distance of the estimate are candidates (0: no radius search)"},
    {"loop_every", &C::loop_every, "", kAtLeastOne, "one node in this many is searched for loops"},
    {"loop_cooldown", &C::loop_cooldown, "", kCount,
     "nodes after a verified loop before the next search"},
    {"verify_coarse_threshold", &C::verify_coarse_threshold, "m", kPositive,
     "first ICP stage's correspondence distance"},
    {"verify_fine_threshold", &C::verify_fine_threshold, "m", kPositive,
     "last ICP stage's correspondence distance (<= verify_coarse_threshold)"},
    {"verify_overlap_distance", &C::verify_overlap_distance, "m", kPositive,
     "a point overlaps when a point of the candidate's map is this close"},
    {"verify_min_overlap", &C::verify_min_overlap, "", kUnit,
     "share of the query's points that must overlap"},
    {"verify_min_structure_overlap", &C::verify_min_structure_overlap, "", kUnit,
     "share of its points above the ground that must overlap"},
    {"verify_max_correction", &C::verify_max_correction, "m", kPositive,
     "largest move of ICP from the initial guess"},
    {"odometry_sigma_m", &C::odometry_sigma_m, "m", kPositive,
     "odometry edges' standard deviation in translation"},
    {"odometry_sigma_deg", &C::odometry_sigma_deg, "deg", kPositive,
     "odometry edges' standard deviation in rotation"},
    {"loop_sigma_m", &C::loop_sigma_m, "m", kPositive,
     "loop edges' standard deviation in translation"},
    {"loop_sigma_deg", &C::loop_sigma_deg, "deg", kPositive,
     "loop edges' standard deviation in rotation"},
    {"optimize_every", &C::optimize_every, "", kAtLeastOne,
     "nodes between optimisations while loops come in"},
    {"max_iterations",
     &C::max_iterations,
     "",
     {1.0, 10000.0},
     "Levenberg-Marquardt iterations per optimisation"},
};

ParameterKind kindOf(const Field& f) {
  if (std::holds_alternative<std::size_t C::*>(f)) return ParameterKind::Count;
  if (std::holds_alternative<int C::*>(f)) return ParameterKind::Integer;
  return ParameterKind::Real;
}

double valueOf(const C& c, const Field& f) {
  if (auto d = std::get_if<double C::*>(&f)) return c.**d;
  if (auto n = std::get_if<std::size_t C::*>(&f)) return static_cast<double>(c.**n);
  return c.*std::get<int C::*>(f);
}

ParameterSpec specOf(const Entry& e, const C& defaults) {
  return {e.name,  kindOf(e.field), e.unit,
          e.range, e.doc,           formatNumber(valueOf(defaults, e.field))};
}

const Entry& find(const std::string& name) {
  for (const Entry& e : kFields)
    if (name == e.name) return e;
  throw std::invalid_argument("unknown slam3d parameter '" + quoteForMessage(name) + "'");
}

}  // namespace

std::vector<ParameterSpec> slam3DParameterSchema() {
  const C defaults;
  std::vector<ParameterSpec> out;
  for (const Entry& e : kFields) out.push_back(specOf(e, defaults));
  return out;
}

void validateSlam3DConfig(const Slam3DConfig& config) {
  const C defaults;
  for (const Entry& e : kFields) checkParameter(specOf(e, defaults), valueOf(config, e.field));
  if (!(config.max_range > config.min_range))
    throw std::invalid_argument("max_range must be > min_range, got " +
                                formatNumber(config.max_range) +
                                " <= " + formatNumber(config.min_range));
  if (config.verify_fine_threshold > config.verify_coarse_threshold)
    throw std::invalid_argument("verify_fine_threshold must be <= verify_coarse_threshold, got " +
                                formatNumber(config.verify_fine_threshold) + " > " +
                                formatNumber(config.verify_coarse_threshold));
}

std::vector<std::string> slam3DParameterNames() {
  std::vector<std::string> out;
  for (const Entry& e : kFields) out.push_back(e.name);
  return out;
}

double slam3DParameterValue(const Slam3DConfig& config, const std::string& name) {
  return valueOf(config, find(name).field);
}

void setSlam3DParameterValue(Slam3DConfig& config, const std::string& name, double value) {
  const Entry& e = find(name);
  checkParameter(specOf(e, C()), value);
  if (auto d = std::get_if<double C::*>(&e.field))
    config.** d = value;
  else if (auto n = std::get_if<std::size_t C::*>(&e.field))
    config.** n = static_cast<std::size_t>(value);
  else
    config.*std::get<int C::*>(e.field) = static_cast<int>(value);
}

void setSlam3DParameter(Slam3DConfig& config, const std::string& name, const std::string& text) {
  const Entry& e = find(name);
  const double v = kindOf(e.field) == ParameterKind::Real
                       ? parseFiniteDouble(text, name)
                       : static_cast<double>(parseInteger(text, name, -(1LL << 40), 1LL << 40));
  setSlam3DParameterValue(config, name, v);
}

}  // namespace metricmap
