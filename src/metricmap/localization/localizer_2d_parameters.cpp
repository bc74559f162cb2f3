#include "metricmap/localization/localizer_2d_parameters.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <variant>

#include "metricmap/common/parse_number.h"

namespace metricmap {
namespace {

using C = Localizer2DConfig;
using Field = std::variant<double C::*, std::size_t C::*, int C::*>;

struct Entry {
  const char* name;
  Field field;
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> list = {
      {"min_range", &C::min_range},
      {"max_range", &C::max_range},
      {"voxel_filter", &C::voxel_filter},
      {"occupied_probability", &C::occupied_probability},
      {"free_probability", &C::free_probability},
      {"branch_and_bound_depth", &C::branch_and_bound_depth},
      {"global_coarsening", &C::global_coarsening},
      {"global_search_points", &C::global_search_points},
      {"global_min_score", &C::global_min_score},
      {"global_min_margin", &C::global_min_margin},
      {"global_max_crossing", &C::global_max_crossing},
      {"global_crossing_clearance", &C::global_crossing_clearance},
      {"global_distinct_distance", &C::global_distinct_distance},
      {"global_distinct_angle_deg", &C::global_distinct_angle_deg},
      {"global_min_motion", &C::global_min_motion},
      {"global_min_turn_deg", &C::global_min_turn_deg},
      {"global_every_n_scans", &C::global_every_n_scans},
      {"initial_linear_window", &C::initial_linear_window},
      {"initial_angular_window_deg", &C::initial_angular_window_deg},
      {"track_linear_window", &C::track_linear_window},
      {"track_angular_window_deg", &C::track_angular_window_deg},
      {"track_angular_window_per_turn", &C::track_angular_window_per_turn},
      {"translation_weight", &C::translation_weight},
      {"rotation_weight", &C::rotation_weight},
      {"refine_iterations", &C::refine_iterations},
      {"track_min_score", &C::track_min_score},
      {"lost_after_weak_scans", &C::lost_after_weak_scans},
  };
  return list;
}

const Entry& find(const std::string& name) {
  for (const Entry& e : entries())
    if (name == e.name) return e;
  throw std::invalid_argument("unknown localisation parameter '" + quoteForMessage(name) + "'");
}

}  // namespace

std::vector<std::string> localizer2DParameterNames() {
  std::vector<std::string> out;
  for (const Entry& e : entries()) out.push_back(e.name);
  return out;
}

std::string localizer2DParameter(const C& config, const std::string& name) {
  const Field& f = find(name).field;
  if (auto n = std::get_if<std::size_t C::*>(&f)) return std::to_string(config.**n);
  if (auto i = std::get_if<int C::*>(&f)) return std::to_string(config.**i);
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", config.*std::get<double C::*>(f));
  return buf;
}

void setLocalizer2DParameter(C& config, const std::string& name, const std::string& value) {
  const Field& f = find(name).field;
  if (auto n = std::get_if<std::size_t C::*>(&f)) {
    config.** n = static_cast<std::size_t>(
        parseInteger(value, name, 0, std::numeric_limits<std::int32_t>::max()));
  } else if (auto i = std::get_if<int C::*>(&f)) {
    config.** i =
        static_cast<int>(parseInteger(value, name, std::numeric_limits<std::int32_t>::min(),
                                      std::numeric_limits<std::int32_t>::max()));
  } else {
    config.*std::get<double C::*>(f) = parseFiniteDouble(value, name);
  }
}

}  // namespace metricmap
