// libFuzzer target for the sequence layer's file readers: any bytes as a trajectory (KITTI or
// TUM rows), a stamps file, a relations file, a g2o pose graph, a .npy point array and a scan
// file with per-point time fields must either read or raise InputError / CapacityError, never
// crash, hang or allocate without bound.
#include <cstdint>
#include <fstream>
#include <string>

#include <unistd.h>

#include <pcl/console/print.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/npy_reader.h"
#include "metricmap/io/scan_file.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/io/trajectory_relations.h"
#include "metricmap/posegraph/g2o_io.h"

namespace {

template <class F>
void tolerate(F&& f) {
  try {
    f();
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = [] {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    metricmap::setMemoryBudget(256u << 20);
    return true;
  }();
  (void)quiet;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::string base = "/tmp/metricmap_fuzz_seq_" + std::to_string(::getpid());
  const bool binary = bytes.rfind("\x93NUMPY", 0) == 0;
  const bool pcd = bytes.find("DATA") != std::string::npos;
  const std::string path = base + (binary ? ".npy" : pcd ? ".pcd" : ".txt");
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(size));
  if (binary) {
    tolerate([&] { metricmap::readNpyPoints(path); });
    tolerate([&] { metricmap::readScanFile(path); });
  } else if (pcd) {
    tolerate([&] { metricmap::readScanFile(path); });
  } else {
    tolerate([&] { metricmap::readTrajectoryFile(path); });
    tolerate([&] { metricmap::readStamps(path); });
    tolerate([&] { metricmap::readRelations(path); });
    tolerate([&] { metricmap::readG2o(path); });
  }
  ::unlink(path.c_str());
  return 0;
}
