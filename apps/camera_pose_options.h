#pragma once
/// \file camera_pose_options.h
/// \brief Where a depth camera stands: --camera-height (with --pitch-deg, --yaw-deg),
/// --pose-matrix, --trajectory or --auto-floor, exactly one (heightmap).

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "metricmap/mapping/height_map_builder.h"

namespace metricmap::cli {

struct CameraPoseOptions {
  double camera_height = NAN, pitch_deg = 0.0, yaw_deg = 0.0;
  std::string pose_matrix, trajectory;
  bool auto_floor = false;
  double floor_distance = 0.02;  ///< the floor fit's inlier distance (m); not an option
};

/// \brief Adds the options.
void addCameraPoseOptions(CLI::App& app, CameraPoseOptions& o);

/// \brief Exactly one pose source, and no --pitch-deg or --yaw-deg without --camera-height:
/// usage errors (exit 2).
void checkCameraPoseOptions(const CLI::App& app, const CameraPoseOptions& o);

/// \brief The poses of `frames` frames: --pose-matrix parsed and checked, the camera of
/// --camera-height, or --trajectory read (one pose line per frame, no more).
HeightMapPoses resolveCameraPoses(const CameraPoseOptions& o, std::size_t frames);

/// \brief A list option through the checked parser; a refused list is a usage error (exit 2).
std::vector<double> parseNumbersOption(const std::string& text, const std::string& what);

}  // namespace metricmap::cli
