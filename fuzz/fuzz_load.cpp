// libFuzzer target for the loading paths: any bytes, as .pcd/.ply/.bin and as a 2D scan log, must
// either load or raise InputError, never crash, hang or allocate without bound; what loads is
// then binned or segmented.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

#include <pcl/console/print.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/lines/split_and_merge.h"
#include "metricmap/octree/adaptive_octree.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = [] {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    metricmap::setMemoryBudget(256u << 20);  // declared sizes above it are CapacityErrors
    return true;
  }();
  (void)quiet;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const char* ext = bytes.rfind("ply", 0) == 0                ? ".ply"
                    : bytes.find("DATA") != std::string::npos ? ".pcd"
                                                              : ".bin";
  const std::string path = "/tmp/metricmap_fuzz_" + std::to_string(::getpid()) + ext;
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(size));
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  try {
    metricmap::loadCloud(path, *cloud);
    metricmap::OccupancyGrid<pcl::PointXYZ> grid;
    grid.setCellSize(0.5f);
    grid.setInputCloud(cloud);
    grid.compute();
    metricmap::AdaptiveOctree<pcl::PointXYZ> octree;
    octree.setMaxPointsPerLeaf(4);
    octree.setMinCellSize(0.01f);
    octree.setInputCloud(cloud);
    octree.compute();
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  }
  // The same bytes as a 2D scan log, through each scan reader and Split & Merge.
  using Reader = metricmap::ScanLog (*)(const std::string&);
  static const Reader readers[] = {metricmap::readAngleRangeCsv, metricmap::readCarmenLog,
                                   [](const std::string& p) {
                                     return metricmap::readScanLines(
                                         p, metricmap::urg04lxMinesFormat());
                                   },
                                   [](const std::string& p) {
                                     metricmap::ScanLineFormat f;
                                     f.count = 4;
                                     return metricmap::readScanLines(p, f);
                                   }};
  for (const Reader read : readers) {
    try {
      const metricmap::ScanLog log = read(path);
      metricmap::SplitAndMerge<pcl::PointXYZ> sam;
      sam.setInputCloud(std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(
          metricmap::scanToCloud(log.scans.front())));
      std::vector<metricmap::LineSegment> segments;
      std::vector<pcl::PointIndices> members;
      sam.segment(segments, members);
    } catch (const metricmap::InputError&) {
    } catch (const metricmap::CapacityError&) {  // scans of a compressed log past the budget
    }
  }
  std::remove(path.c_str());
  return 0;
}
