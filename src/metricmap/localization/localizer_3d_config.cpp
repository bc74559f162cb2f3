#include "metricmap/localization/localizer_3d_config.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace metricmap {
namespace {

void positive(double v, const char* name) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(name) + " must be finite and > 0");
}
void nonNegative(double v, const char* name) {
  if (!(v >= 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(name) + " must be finite and >= 0");
}
void share(double v, const char* name) {
  if (!(v >= 0.0 && v <= 1.0))
    throw std::invalid_argument(std::string(name) + " must be in [0, 1]");
}
void count(int v, int lo, int hi, const char* name) {
  if (v < lo || v > hi)
    throw std::invalid_argument(std::string(name) + " must be in " + std::to_string(lo) + ".." +
                                std::to_string(hi));
}

}  // namespace

void validateLocalizer3DConfig(const Localizer3DConfig& c) {
  nonNegative(c.min_range, "min_range");
  positive(c.max_range, "max_range");
  if (!(c.max_range > c.min_range)) throw std::invalid_argument("max_range must exceed min_range");
  positive(c.scan_voxel, "scan_voxel");
  positive(c.map_voxel, "map_voxel");
  count(c.map_points_per_voxel, 1, 1000, "map_points_per_voxel");
  positive(c.place_spacing, "place_spacing");
  positive(c.place_cell, "place_cell");
  if (c.place_cell > c.place_spacing)
    throw std::invalid_argument("place_cell must be <= place_spacing");
  positive(c.place_clearance, "place_clearance");
  count(c.place_min_ground_points, 1, 1000000, "place_min_ground_points");
  positive(c.clip_height, "clip_height");
  nonNegative(c.clip_slope, "clip_slope");
  validateScanContextParams(c.descriptor);
  positive(c.ground_threshold, "ground_threshold");
  if (!(c.ground_max_tilt_deg > 0.0 && c.ground_max_tilt_deg < 90.0))
    throw std::invalid_argument("ground_max_tilt_deg must be in (0, 90)");
  count(c.global_candidates, 1, 1000, "global_candidates");
  validateLoopVerificationParams(c.verify);
  share(c.global_min_margin, "global_min_margin");
  positive(c.global_distinct_distance, "global_distinct_distance");
  positive(c.global_distinct_angle_deg, "global_distinct_angle_deg");
  positive(c.track_coarse_threshold, "track_coarse_threshold");
  positive(c.track_fine_threshold, "track_fine_threshold");
  if (c.track_fine_threshold > c.track_coarse_threshold)
    throw std::invalid_argument("track_fine_threshold must be <= track_coarse_threshold");
  nonNegative(c.track_yaw_window_deg, "track_yaw_window_deg");
  positive(c.track_yaw_step_deg, "track_yaw_step_deg");
  count(c.track_iterations, 1, 1000, "track_iterations");
  positive(c.overlap_distance, "overlap_distance");
  share(c.track_min_overlap, "track_min_overlap");
  count(c.lost_after_weak_scans, 1, 1000000, "lost_after_weak_scans");
  positive(c.track_max_correction, "track_max_correction");
}

}  // namespace metricmap
