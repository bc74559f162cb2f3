#include "metricmap/slam/slam_2d_parameters.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <variant>

#include "metricmap/common/parse_number.h"

namespace metricmap {
namespace {

using Field = std::variant<double Slam2DConfig::*, std::size_t Slam2DConfig::*, int Slam2DConfig::*,
                           bool Slam2DConfig::*, double LogOddsParams::*>;

struct Entry {
  const char* name;
  Field field;
};

const std::vector<Entry>& entries() {
  using C = Slam2DConfig;
  using M = LogOddsParams;
  static const std::vector<Entry> list = {
      {"min_range", &C::min_range},
      {"max_range", &C::max_range},
      {"voxel_filter", &C::voxel_filter},
      {"resolution", &C::resolution},
      {"scans_per_submap", &C::scans_per_submap},
      {"prob_hit", &C::prob_hit},
      {"prob_miss", &C::prob_miss},
      {"node_min_distance", &C::node_min_distance},
      {"node_min_angle_deg", &C::node_min_angle_deg},
      {"node_max_time", &C::node_max_time},
      {"local_linear_window", &C::local_linear_window},
      {"local_angular_window_deg", &C::local_angular_window_deg},
      {"local_angular_window_per_turn", &C::local_angular_window_per_turn},
      {"weak_direction_min_gain", &C::weak_direction_min_gain},
      {"weak_direction_information", &C::weak_direction_information},
      {"weak_direction_weight", &C::weak_direction_weight},
      {"translation_weight", &C::translation_weight},
      {"rotation_weight", &C::rotation_weight},
      {"refine_iterations", &C::refine_iterations},
      {"bicubic", &C::bicubic},
      {"loop_linear_window", &C::loop_linear_window},
      {"loop_angular_window_deg", &C::loop_angular_window_deg},
      {"loop_min_score", &C::loop_min_score},
      {"loop_max_distance", &C::loop_max_distance},
      {"wide_min_node_gap", &C::wide_min_node_gap},
      {"wide_every_n_nodes", &C::wide_every_n_nodes},
      {"wide_idle_nodes", &C::wide_idle_nodes},
      {"wide_linear_window", &C::wide_linear_window},
      {"wide_angular_window_deg", &C::wide_angular_window_deg},
      {"loop_every_n_nodes", &C::loop_every_n_nodes},
      {"loop_min_node_gap", &C::loop_min_node_gap},
      {"loop_min_overlap", &C::loop_min_overlap},
      {"loop_max_chi2", &C::loop_max_chi2},
      {"loop_max_submaps", &C::loop_max_submaps},
      {"loop_search_points", &C::loop_search_points},
      {"branch_and_bound_depth", &C::branch_and_bound_depth},
      {"edge_translation_sigma", &C::edge_translation_sigma},
      {"edge_rotation_sigma_deg", &C::edge_rotation_sigma_deg},
      {"loop_translation_sigma", &C::loop_translation_sigma},
      {"loop_rotation_sigma_deg", &C::loop_rotation_sigma_deg},
      {"optimize_every_n_nodes", &C::optimize_every_n_nodes},
      {"optimize_iterations", &C::optimize_iterations},
      {"final_iterations", &C::final_iterations},
      {"map_resolution", &M::resolution},
      {"map_prob_hit", &M::prob_hit},
      {"map_prob_miss", &M::prob_miss},
      {"map_clamp_min", &M::clamp_min},
      {"map_clamp_max", &M::clamp_max},
      {"map_occupancy_threshold", &M::occupancy_threshold},
      {"map_max_range", &M::max_range},
  };
  return list;
}

// Levenshtein distance, for "did you mean".
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

const Entry& find(const std::string& name) {
  const Entry* nearest = nullptr;
  std::size_t best = std::numeric_limits<std::size_t>::max();
  for (const Entry& e : entries()) {
    if (name == e.name) return e;
    const std::size_t d = distance(name, e.name);
    if (d < best) best = d, nearest = &e;
  }
  std::string msg = "unknown SLAM parameter '" + quoteForMessage(name) + "'";
  if (nearest && best <= 3) msg += " (did you mean " + std::string(nearest->name) + "?)";
  throw std::invalid_argument(msg);
}

std::string text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

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

}  // namespace metricmap
