// libFuzzer target for KITTI files: any bytes as a velodyne .bin cloud, a calib.txt and a poses
// file. Each gives a result or an InputError / CapacityError / std::invalid_argument.
#include <cstdint>
#include <stdexcept>

#include <pcl/console/print.h>

#include "fuzz_common.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool init = [] {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    metricmap::setMemoryBudget(64u << 20);
    return true;
  }();
  (void)init;
  {
    metricmap::fuzz::TempInput input(data, size, "kitti", ".bin");
    pcl::PointCloud<pcl::PointXYZI> cloud;
    try {
      metricmap::loadCloud(input.path(), cloud);
    } catch (const metricmap::InputError&) {
    } catch (const metricmap::CapacityError&) {
    }
  }
  metricmap::fuzz::TempInput text(data, size, "kitti", ".txt");
  try {
    metricmap::readKittiCalibTr(text.path());
  } catch (const metricmap::InputError&) {
  } catch (const std::invalid_argument&) {
  }
  try {
    metricmap::readKittiPoses(text.path(), 3);
  } catch (const metricmap::InputError&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
