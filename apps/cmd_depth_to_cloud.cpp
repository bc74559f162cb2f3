// metricmap depth-to-cloud DEPTH: an organized PCD from a depth image and intrinsics.
#include <cmath>
#include <memory>

#include <nlohmann/json.hpp>

#include "camera_options.h"
#include "cli_common.h"
#include "commands.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/io/cloud_writer.h"

namespace metricmap::cli {
namespace {

struct DepthToCloudOptions {
  std::string depth, rgb, out, pcd_format = "binary";
  CameraOptions camera;
};

template <typename Cloud>
std::size_t finitePoints(const Cloud& cloud) {
  std::size_t n = 0;
  for (const auto& p : cloud) n += std::isfinite(p.z) ? 1 : 0;
  return n;
}

void run(const DepthToCloudOptions& o) {
  requireDistinctFiles(
      {{"depth image", o.depth}, {"--rgb image", o.rgb}, {"--camera file", o.camera.camera_file}},
      {{"--out", o.out}});
  requireExtension("--out", o.out, {".pcd"}, "a PCD cloud");
  const DepthImage depth = readDepthImage(o.depth);
  const CameraIntrinsics k = resolveIntrinsics(o.camera, depth);
  const double scale = resolveDepthScale(o.camera, k, depth);
  std::size_t valid = 0;
  OutputSet outputs;  // committed once the report is printed
  if (o.rgb.empty()) {
    const auto cloud = depthToCloud(depth, k, scale);
    savePcdAtomic(outputs.stage(o.out), cloud, parsePcdFormat(o.pcd_format));
    valid = finitePoints(cloud);
  } else {
    const auto cloud = depthToCloud(depth, k, scale, readRgbImage(o.rgb));
    savePcdAtomic(outputs.stage(o.out), cloud, parsePcdFormat(o.pcd_format));
    valid = finitePoints(cloud);
  }
  emit(nlohmann::json({{"depth", o.depth},
                       {"out", o.out},
                       {"width", depth.width},
                       {"height", depth.height},
                       {"valid_points", valid},
                       {"depth_scale", scale},
                       {"intrinsics", {k.fx, k.fy, k.cx, k.cy}}})
               .dump() +
           "\n",
       outputs);
}

}  // namespace

void addDepthToCloudCommand(CLI::App& app) {
  auto o = std::make_shared<DepthToCloudOptions>();
  CLI::App* sub = app.add_subcommand("depth-to-cloud", "Organized PCD from a 16-bit depth image");
  sub->add_option("depth", o->depth, "16-bit depth image (.png, .tif, .tiff)")->required();
  sub->add_option("--rgb", o->rgb, "Registered 8-bit RGB image: write x y z rgb");
  addCameraOptions(*sub, o->camera);
  sub->add_option("--out", o->out, "Output .pcd")->required()->check(kOutputFile);
  addPcdFormatOption(*sub, o->pcd_format);
  sub->callback([o] { run(*o); });
}

}  // namespace metricmap::cli
