#include "metricmap/localization/localizer_2d_config.h"

#include <cmath>
#include <stdexcept>

namespace metricmap {

void validateLocalizer2DConfig(const Localizer2DConfig& c) {
  auto need = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(what);
  };
  // The ranges below are the command's too (its options check the same bounds).
  need(c.min_range >= 0 && c.min_range <= 1e4, "min_range must be in [0, 10000] m");
  need(c.max_range >= 0.01 && c.max_range <= 1e4, "max_range must be in [0.01, 10000] m");
  need(c.max_range > c.min_range, "max_range must be greater than min_range");
  need(c.voxel_filter >= 0.001 && c.voxel_filter <= 10, "voxel_filter must be in [0.001, 10] m");
  need(c.occupied_probability > 0.5 && c.occupied_probability < 1,
       "occupied_probability must be in (0.5, 1)");
  need(c.free_probability > 0 && c.free_probability < 0.5, "free_probability must be in (0, 0.5)");
  need(c.branch_and_bound_depth >= 1 && c.branch_and_bound_depth <= 16,
       "branch_and_bound_depth must be in 1..16");
  need(c.global_coarsening >= 1 && c.global_coarsening <= 8, "global_coarsening must be in 1..8");
  need(c.global_search_points >= 10, "global_search_points must be >= 10");
  need(c.global_min_score >= 0.01 && c.global_min_score <= 0.99,
       "global_min_score must be in [0.01, 0.99]");
  need(c.global_min_margin >= 0 && c.global_min_margin <= 1, "global_min_margin must be in [0, 1]");
  need(c.global_max_crossing >= 0 && c.global_max_crossing <= 1,
       "global_max_crossing must be in [0, 1]");
  need(std::isfinite(c.global_crossing_clearance) && c.global_crossing_clearance >= 0,
       "global_crossing_clearance must be >= 0");
  need(std::isfinite(c.global_distinct_distance) && c.global_distinct_distance > 0,
       "global_distinct_distance must be > 0");
  need(c.global_distinct_angle_deg > 0 && c.global_distinct_angle_deg <= 180,
       "global_distinct_angle_deg must be in (0, 180]");
  need(std::isfinite(c.global_min_motion) && c.global_min_motion >= 0,
       "global_min_motion must be >= 0");
  need(std::isfinite(c.global_min_turn_deg) && c.global_min_turn_deg >= 0,
       "global_min_turn_deg must be >= 0");
  need(c.global_every_n_scans >= 1, "global_every_n_scans must be >= 1");
  need(std::isfinite(c.initial_linear_window) && c.initial_linear_window > 0 &&
           c.initial_linear_window <= 100,
       "initial_linear_window must be in (0, 100] m");
  need(c.initial_angular_window_deg > 0 && c.initial_angular_window_deg <= 180,
       "initial_angular_window_deg must be in (0, 180]");
  need(std::isfinite(c.track_linear_window) && c.track_linear_window >= 0 &&
           c.track_linear_window <= 10,
       "track_linear_window must be in [0, 10] m");
  need(c.track_angular_window_deg >= 0 && c.track_angular_window_deg <= 180,
       "track_angular_window_deg must be in [0, 180]");
  need(c.track_angular_window_per_turn >= 0 && c.track_angular_window_per_turn <= 10,
       "track_angular_window_per_turn must be in [0, 10]");
  need(std::isfinite(c.translation_weight) && c.translation_weight >= 0,
       "translation_weight must be >= 0");
  need(std::isfinite(c.rotation_weight) && c.rotation_weight >= 0, "rotation_weight must be >= 0");
  need(c.refine_iterations >= 1 && c.refine_iterations <= 1000,
       "refine_iterations must be in 1..1000");
  need(c.track_min_score >= 0.01 && c.track_min_score <= 0.99,
       "track_min_score must be in [0.01, 0.99]");
  need(c.lost_after_weak_scans >= 1 && c.lost_after_weak_scans <= 1000000,
       "lost_after_weak_scans must be in 1..1000000");
}

}  // namespace metricmap
