// libFuzzer target for the depth path: any bytes as PNG and as TIFF, read as a depth image and as
// an RGB image, then projected. Every outcome is a cloud or an InputError/CapacityError; a
// 64 MiB budget keeps declared sizes from allocating without bound.
#include <cstdint>
#include <stdexcept>

#include "fuzz_common.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/depth_image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool budget = [] {
    metricmap::setMemoryBudget(64u << 20);
    return true;
  }();
  (void)budget;
  for (const char* ext : {".png", ".tiff"}) {
    metricmap::fuzz::TempInput input(data, size, "depth", ext);
    try {
      const metricmap::DepthImage depth = metricmap::readDepthImage(input.path());
      metricmap::CameraIntrinsics k;
      k.fx = k.fy = 525.0;
      k.cx = depth.width / 2.0;
      k.cy = depth.height / 2.0;
      const auto cloud = metricmap::depthToCloud(depth, k, 0.001);
      if (cloud.size() != depth.values.size()) __builtin_trap();
    } catch (const metricmap::InputError&) {
    } catch (const metricmap::CapacityError&) {
    }
    try {
      metricmap::readRgbImage(input.path());
    } catch (const metricmap::InputError&) {
    } catch (const metricmap::CapacityError&) {
    }
  }
  return 0;
}
