#pragma once
/// \file slam3d_config.h
/// \brief Parameters of the 3D LiDAR SLAM (Slam3D) and their defaults, declared once in
/// slam3DParameterSchema() (slam3d_parameters.h).

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/common/parameter_schema.h"

namespace metricmap {

/// \brief Everything Slam3D can be told.
struct Slam3DConfig {
  // --- nodes (every scan given is a node of the pose graph)
  double min_range = 1.0;   ///< points closer to the sensor are dropped (m)
  double max_range = 80.0;  ///< farther ones too (m)
  double voxel = 0.5;       ///< each node keeps one point per voxel of this edge (m)

  // --- local maps and place recognition
  std::size_t local_window = 5;    ///< a node's local map: its scans and this many either side
  double local_voxel = 0.5;        ///< local maps keep one point per voxel of this edge (m)
  int sc_rings = 20;               ///< Scan Context range bins
  int sc_sectors = 60;             ///< Scan Context azimuth bins
  double sc_max_radius = 40.0;     ///< Scan Context radius (m)
  double sc_height_offset = 2.0;   ///< added to heights above the sensor before binning (m)
  std::size_t sc_candidates = 10;  ///< nearest ring keys compared in full
  double sc_max_distance = 0.3;    ///< Scan Context distance a candidate must be below
  double loop_min_travel = 40.0;   ///< a candidate lies at least this far back along the path (m)
  double loop_radius = 10.0;      ///< nodes within this distance of the estimate are candidates (m)
  std::size_t loop_every = 2;     ///< one node in this many is searched for loops
  std::size_t loop_cooldown = 3;  ///< nodes after a verified loop before the next search

  // --- verification (loop_verification.h)
  double verify_coarse_threshold = 3.0;
  double verify_fine_threshold = 0.5;
  double verify_overlap_distance = 0.4;
  double verify_min_overlap = 0.5;
  double verify_min_structure_overlap = 0.35;
  double verify_max_correction = 8.0;

  // --- pose graph
  double odometry_sigma_m = 0.1;    ///< odometry edges' standard deviation in translation (m)
  double odometry_sigma_deg = 1.0;  ///< ... in rotation (deg)
  double loop_sigma_m = 0.1;        ///< loop edges' (m)
  double loop_sigma_deg = 0.5;      ///< loop edges' (deg)
  std::size_t optimize_every = 10;  ///< nodes between optimisations while loops come in
  int max_iterations = 50;          ///< Levenberg-Marquardt iterations per optimisation
};

/// \brief Every field: name, kind, unit, range, doc, default.
std::vector<ParameterSpec> slam3DParameterSchema();
/// \brief \throws std::invalid_argument "NAME must be RULE, got VALUE" for the first bad field
void validateSlam3DConfig(const Slam3DConfig& config);
/// \brief Names in declaration order.
std::vector<std::string> slam3DParameterNames();
/// \brief A field's value as a number (counts and integers exact). \throws std::invalid_argument
double slam3DParameterValue(const Slam3DConfig& config, const std::string& name);
/// \brief Set a field from a number, range-checked. \throws std::invalid_argument naming it
void setSlam3DParameterValue(Slam3DConfig& config, const std::string& name, double value);
/// \brief Set a field from text ("NAME=VALUE" of --set), parsed and range-checked.
void setSlam3DParameter(Slam3DConfig& config, const std::string& name, const std::string& text);

}  // namespace metricmap
