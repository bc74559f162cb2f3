#include "camera_options.h"

#include "cli_common.h"
#include "metricmap/camera/depth_to_cloud.h"

namespace metricmap::cli {

void addCameraOptions(CLI::App& app, CameraOptions& o) {
  auto* group = app.add_option_group("intrinsics", "Camera intrinsics (exactly one)");
  group->add_option("--camera", o.camera_file, "PCL grabber .xml or Open3D camera .json");
  group->add_option("--intrinsics", o.intrinsics, "fx,fy,cx,cy in pixels")
      ->check(CLI::Validator(
          [](std::string& s) -> std::string {
            try {
              parseIntrinsics(s);  // four finite numbers, fx, fy > 0: else a usage error
            } catch (const std::invalid_argument& e) {
              return e.what();
            }
            return std::string();
          },
          "FX,FY,CX,CY"));
  group->add_option("--hfov-deg", o.hfov_deg, "Horizontal field of view, degrees")
      ->check(kFinitePositive & finiteIn(0.0, 179.999));
  group->require_option(1);
  app.add_option("--depth-scale", o.depth_scale, "Metres per raw depth unit")
      ->check(kFinitePositive);
}

CameraIntrinsics resolveIntrinsics(const CameraOptions& o, const DepthImage& depth) {
  CameraIntrinsics k;
  if (!o.camera_file.empty()) {
    k = readCameraFile(o.camera_file);
  } else if (!o.intrinsics.empty()) {
    k = parseIntrinsics(o.intrinsics);
  } else {
    k = intrinsicsFromHfov(o.hfov_deg, depth.width, depth.height);
  }
  if (k.width > 0 && (k.width != depth.width || k.height != depth.height)) {
    throw std::invalid_argument("the camera is " + std::to_string(k.width) + "x" +
                                std::to_string(k.height) + ", the depth image " +
                                std::to_string(depth.width) + "x" + std::to_string(depth.height));
  }
  return k;
}

double resolveDepthScale(const CameraOptions& o, const CameraIntrinsics& k,
                         const DepthImage& depth) {
  return depthScaleFor(depth, k, o.depth_scale);
}

}  // namespace metricmap::cli
