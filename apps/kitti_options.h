#pragma once
/// \file kitti_options.h
/// \brief The options of `metricmap kitti`, their checks, and the library run they ask for.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "metricmap/occupancy/log_odds_params.h"
#include "metricmap/sequence/kitti_mapping.h"

namespace metricmap::cli {

struct KittiOptions {
  std::string root, sequence = "00", frames, world = "camera", out_cloud, out_map;
  std::string pcd_format = "binary", map_plane = "xz", format = "table", refine, perturb;
  std::string refine_target = "map", out_poses, poses = "file";
  std::string out_octomap, out_trinary, band;  // 3D occupancy outputs
  double occupancy_resolution = 0.0, occupancy_max_range = LogOddsParams{}.max_range;
  unsigned seed = 1;
  long long first = -1, count = 0, min_hits = 1;
  ScanMapperConfig mapper;  // ranges, voxel, height band, map resolution: its defaults
};

/// \brief --voxel: 0 (off) or a voxel edge a float holds as a normal number (the voxel grid is
/// float: 1e308 would become inf and be reported as such).
extern const CLI::Validator kVoxelSize;
/// \brief --perturb T,R: 0 <= T <= 100 (m), 0 <= R <= 180 (degrees).
extern const CLI::Validator kPerturbation;
/// \brief --band zmin,zmax.
extern const CLI::Validator kBand;

/// \brief The run the options ask for, after the usage checks (exit 2) in this order: options
/// that would have no effect, the frame selection, --perturb with --poses odometry, the mapper's
/// configuration. \throws CLI::ValidationError, UsageError
KittiMappingOptions kittiMappingOptions(const KittiOptions& o, const CLI::App& app);

}  // namespace metricmap::cli
