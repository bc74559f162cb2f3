#include "metricmap/camera/depth_to_cloud.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/common/memory_budget.h"

namespace metricmap {
namespace {

void check(const DepthImage& depth, const CameraIntrinsics& k, double depth_scale) {
  validateIntrinsics(k);
  if (!std::isfinite(depth_scale) || !(depth_scale > 0.0)) {
    throw std::invalid_argument("depth scale must be a finite number > 0, got " +
                                formatNumber(depth_scale));
  }
  if (depth.width <= 0 || depth.height <= 0) throw std::invalid_argument("empty depth image");
}

template <typename PointT, typename Fill>
pcl::PointCloud<PointT> project(const DepthImage& depth, const CameraIntrinsics& k,
                                double depth_scale, Fill fill) {
  check(depth, k, depth_scale);
  checkMemory(static_cast<std::uint64_t>(depth.width) * static_cast<std::uint64_t>(depth.height),
              sizeof(PointT),
              "the cloud of a " + std::to_string(depth.width) + " x " +
                  std::to_string(depth.height) + " depth image");
  pcl::PointCloud<PointT> cloud(static_cast<std::uint32_t>(depth.width),
                                static_cast<std::uint32_t>(depth.height));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  bool dense = true;
  for (int v = 0; v < depth.height; ++v) {
    for (int u = 0; u < depth.width; ++u) {
      // Flat indexing: a one-row image is organized too (PCL's at(u, v) refuses height 1).
      PointT& p = cloud[static_cast<std::size_t>(v) * depth.width + u];
      const std::uint16_t d = depth.at(u, v);
      fill(p, u, v);
      if (d == 0) {
        p.x = p.y = p.z = nan;
        dense = false;
        continue;
      }
      const double z = d * depth_scale;
      // A depth no float holds would read as 0: a valid pixel at the camera centre
      if (belowFloatRange(z)) {
        throw std::invalid_argument(
            "depth scale " + formatNumber(depth_scale) + " times raw depth " + std::to_string(d) +
            " at pixel (" + std::to_string(u) + ", " + std::to_string(v) + ") gives " +
            formatNumber(z) + " m, below float range (1.17549e-38): it would read as 0");
      }
      p.x = static_cast<float>((u - k.cx) * z / k.fx);
      p.y = static_cast<float>((v - k.cy) * z / k.fy);
      p.z = static_cast<float>(z);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw std::invalid_argument("depth scale " + formatNumber(depth_scale) +
                                    " times raw depth " + std::to_string(d) + " at pixel (" +
                                    std::to_string(u) + ", " + std::to_string(v) +
                                    ") gives a coordinate beyond float range");
      }
    }
  }
  cloud.is_dense = dense;
  return cloud;
}

}  // namespace

double depthScaleFor(const DepthImage& depth, const CameraIntrinsics& k, double given) {
  if (given > 0.0) return given;
  if (k.depth_scale > 0.0) return k.depth_scale;
  return depth.kind == "tiff" ? 0.001 : 0.0002;
}

pcl::PointCloud<pcl::PointXYZ> depthToCloud(const DepthImage& depth, const CameraIntrinsics& k,
                                            double depth_scale) {
  return project<pcl::PointXYZ>(depth, k, depth_scale, [](pcl::PointXYZ&, int, int) {});
}

pcl::PointCloud<pcl::PointXYZRGB> depthToCloud(const DepthImage& depth, const CameraIntrinsics& k,
                                               double depth_scale, const RgbImage& rgb) {
  if (rgb.width != depth.width || rgb.height != depth.height) {
    throw std::invalid_argument("RGB image is " + std::to_string(rgb.width) + "x" +
                                std::to_string(rgb.height) + ", depth image " +
                                std::to_string(depth.width) + "x" + std::to_string(depth.height));
  }
  return project<pcl::PointXYZRGB>(depth, k, depth_scale, [&](pcl::PointXYZRGB& p, int u, int v) {
    const std::size_t i = (static_cast<std::size_t>(v) * rgb.width + u) * 3;
    p.r = rgb.rgb[i];
    p.g = rgb.rgb[i + 1];
    p.b = rgb.rgb[i + 2];
    p.a = 255;
  });
}

}  // namespace metricmap
