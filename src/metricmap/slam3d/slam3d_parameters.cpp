#include <cmath>
#include <limits>
#include <stdexcept>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parameter_table.h"
#include "metricmap/slam3d/slam3d_config.h"

namespace metricmap {
namespace {

using C = Slam3DConfig;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr ParameterRange kPositive{0.0, kInf, true};
constexpr ParameterRange kNonNegative{0.0, kInf, false};
constexpr ParameterRange kAtLeastOne{1.0, 1e6};
constexpr ParameterRange kCount{0.0, 1e6};
constexpr ParameterRange kUnit{0.0, 1.0};

const ParameterTable<C>& table() {
  static const ParameterTable<C> t(
      "slam3d",
      {
          {"min_range", &C::min_range, "m", kNonNegative,
           "points closer to the sensor are dropped"},
          {"max_range", &C::max_range, "m", kPositive, "points farther are dropped (> min_range)"},
          {"voxel",
           &C::voxel,
           "m",
           {0.05, 10.0},
           "each node keeps one point per voxel of this edge"},
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
          {"loop_every", &C::loop_every, "", kAtLeastOne,
           "one node in this many is searched for loops"},
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
      });
  return t;
}

}  // namespace

std::vector<ParameterSpec> slam3DParameterSchema() { return table().schema(); }

void validateSlam3DConfig(const Slam3DConfig& config) {
  table().checkRanges(config);
  if (!(config.max_range > config.min_range))
    throw std::invalid_argument("max_range must be > min_range, got " +
                                formatNumber(config.max_range) +
                                " <= " + formatNumber(config.min_range));
  if (config.verify_fine_threshold > config.verify_coarse_threshold)
    throw std::invalid_argument("verify_fine_threshold must be <= verify_coarse_threshold, got " +
                                formatNumber(config.verify_fine_threshold) + " > " +
                                formatNumber(config.verify_coarse_threshold));
}

std::vector<std::string> slam3DParameterNames() { return table().names(); }

double slam3DParameterValue(const Slam3DConfig& config, const std::string& name) {
  return table().value(config, name);
}

void setSlam3DParameterValue(Slam3DConfig& config, const std::string& name, double value) {
  checkParameter(table().spec(name), value);
  table().setValue(config, name, value);
}

void setSlam3DParameter(Slam3DConfig& config, const std::string& name, const std::string& text) {
  Slam3DConfig trial = config;
  table().setText(trial, name, text);
  setSlam3DParameterValue(config, name, table().value(trial, name));
}

}  // namespace metricmap
