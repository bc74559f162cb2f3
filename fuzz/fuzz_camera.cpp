// libFuzzer target for camera files: any bytes as a PCL grabber .xml and an Open3D .json give
// intrinsics that pass validateIntrinsics, or an InputError.
#include <cstdint>

#include "fuzz_common.h"
#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/exceptions.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (const char* ext : {".xml", ".json"}) {
    metricmap::fuzz::TempInput input(data, size, "camera", ext);
    try {
      const metricmap::CameraIntrinsics k = metricmap::readCameraFile(input.path());
      metricmap::validateIntrinsics(k);  // what a reader returns must be valid
      if (k.depth_scale < 0.0) __builtin_trap();
    } catch (const metricmap::InputError&) {
    }
  }
  return 0;
}
