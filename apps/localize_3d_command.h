#pragma once
/// \file localize_3d_command.h
/// \brief `metricmap localize SOURCE --map MAP.pcd|.ply|.bt|.ot`: the 3D half of the command.

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "metricmap/localization/localizer_3d_config.h"
#include "sequence_options.h"

namespace metricmap::cli {

struct Localize3DCommand {
  SourceOptions source;
  std::string map, out_poses, pose_format = "tum", format = "table";
  std::optional<Eigen::Isometry3d> initial;  ///< base -> map
  Localizer3DConfig config;
};

/// \brief x,y,z,roll,pitch,yaw (m, rad; R = Rz(yaw) Ry(pitch) Rx(roll)) as a pose.
Eigen::Isometry3d poseFromXyzRpy(const std::vector<double>& v);

/// \brief Load the map, localise the source's selected scans, write the poses, print the report.
void runLocalize3DCommand(const Localize3DCommand& c, std::chrono::steady_clock::time_point start);

}  // namespace metricmap::cli
