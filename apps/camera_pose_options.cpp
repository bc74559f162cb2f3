#include "camera_pose_options.h"

#include <stdexcept>

#include "cli_common.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/io/tum_pose_lines.h"
#include "metricmap/mapping/height_map.h"

namespace metricmap::cli {
namespace {

constexpr double kDeg = M_PI / 180.0;

Eigen::Isometry3d poseFromMatrix(const std::string& text) {
  const std::vector<double> m = parseNumbersOption(text, "--pose-matrix");
  if (m.size() != 16)
    throw CLI::ValidationError("--pose-matrix", "needs 16 numbers (row-major 4x4)");
  Eigen::Matrix4d t;
  for (int i = 0; i < 16; ++i) t(i / 4, i % 4) = m[static_cast<std::size_t>(i)];
  try {
    checkRigidTransform(t, "--pose-matrix");  // a zero matrix would collapse every point
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  Eigen::Isometry3d pose;
  pose.matrix() = t;
  return pose;
}

}  // namespace

std::vector<double> parseNumbersOption(const std::string& text, const std::string& what) {
  try {
    return parseDoubleList(text, what);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(what, e.what());
  }
}

void addCameraPoseOptions(CLI::App& app, CameraPoseOptions& o) {
  app.add_option("--camera-height", o.camera_height, "Camera height above the floor, metres")
      ->check(kFiniteNonNegative);
  app.add_option("--pitch-deg", o.pitch_deg, "Camera pitch, degrees (positive: looking down)")
      ->check(finiteIn(-90.0, 90.0));
  app.add_option("--yaw-deg", o.yaw_deg, "Camera yaw, degrees")->check(finiteIn(-360.0, 360.0));
  app.add_option("--pose-matrix", o.pose_matrix, "Camera-to-map 4x4, 16 numbers row-major");
  app.add_option("--trajectory", o.trajectory,
                 "TUM trajectory (timestamp tx ty tz qx qy qz qw), one line per depth image, "
                 "in order (more lines than images: an error)");
  app.add_flag("--auto-floor", o.auto_floor,
               "Fit the floor (RANSAC plane, PCL sample_consensus) and measure heights from it");
}

void checkCameraPoseOptions(const CLI::App& app, const CameraPoseOptions& o) {
  const int sources = (!std::isnan(o.camera_height) ? 1 : 0) + (!o.pose_matrix.empty() ? 1 : 0) +
                      (!o.trajectory.empty() ? 1 : 0) + (o.auto_floor ? 1 : 0);
  if (sources != 1) {
    throw CLI::ValidationError("pose",
                               "give exactly one of --camera-height (with --pitch-deg, "
                               "--yaw-deg), --pose-matrix, --trajectory, --auto-floor");
  }
  // --pitch-deg and --yaw-deg turn the camera of --camera-height; any other pose ignores them.
  for (const char* option : {"--pitch-deg", "--yaw-deg"}) {
    refuseIgnored(app, option, !std::isnan(o.camera_height),
                  "without --camera-height: the pose comes from --pose-matrix, --trajectory or "
                  "--auto-floor");
  }
}

HeightMapPoses resolveCameraPoses(const CameraPoseOptions& o, std::size_t frames) {
  HeightMapPoses poses;
  poses.auto_floor = o.auto_floor;
  poses.floor_distance = o.floor_distance;
  if (!o.pose_matrix.empty()) poses.fixed = poseFromMatrix(o.pose_matrix);
  if (!std::isnan(o.camera_height))
    poses.fixed = cameraToMap(o.camera_height, o.pitch_deg * kDeg, o.yaw_deg * kDeg);
  if (!o.trajectory.empty()) {
    poses.trajectory = readTumTrajectory(o.trajectory, frames);
    requireNoExtraPoses(o.trajectory, frames, "depth image");
  }
  return poses;
}

}  // namespace metricmap::cli
